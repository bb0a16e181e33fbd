/* The reduction section of the C API (wrappers/c/udmap.h) on a small 3D truss blade (bars on
 * the edges and diagonals of a 2 x 12 x 2 node lattice, consistent bar mass plus node masses,
 * root layer clamped, a rigid platform layer, excitation along an oblique direction), against a
 * dense reference built here: T with q = [free DOFs, u_R, theta], K_t = T^T K T, M_t, LAPACK
 * dsygv for the eigenfrequencies in [0, 3 f_max] and dgesv for the static and dynamic
 * receptances of gamma_P. Then bad input: status 2, a message naming the argument, no handle. */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "check.h"
#include "udmap.h"

void dsygv_(const int *itype, const char *jobz, const char *uplo, const int *n, double *a,
            const int *lda, double *b, const int *ldb, double *w, double *work, const int *lwork,
            int *info, size_t, size_t);
void dgesv_(const int *n, const int *nrhs, double *a, const int *lda, int *ipiv, double *b,
            const int *ldb, int *info);

#define NX 2
#define NY 12
#define NZ 2
#define NN (NX * NY * NZ)
#define NDOF (3 * NN)
#define PLATFORM_J 3
#define PI 3.14159265358979323846

static int node_id(int i, int j, int k) { return 101 + (i * NY + j) * NZ + k; } /* non-compact */
static double X[NN][3];
static double K[NDOF][NDOF], M[NDOF][NDOF];

static void bar(int a, int b, double EA, double rhoA) {
  double d[3], L = 0;
  for (int c = 0; c < 3; c++) {
    d[c] = X[b][c] - X[a][c];
    L += d[c] * d[c];
  }
  L = sqrt(L);
  for (int c = 0; c < 3; c++) d[c] /= L;
  int n[2] = {a, b};
  for (int p = 0; p < 2; p++)
    for (int q = 0; q < 2; q++)
      for (int c = 0; c < 3; c++) {
        for (int e = 0; e < 3; e++)
          K[3 * n[p] + c][3 * n[q] + e] += (p == q ? 1 : -1) * EA / L * d[c] * d[e];
        M[3 * n[p] + c][3 * n[q] + c] += rhoA * L / 6 * (p == q ? 2 : 1);
      }
}

static int idx(int i, int j, int k) { return (i * NY + j) * NZ + k; }

int main(void) {
  /* lattice 10 mm x 8 mm pitch in y, steel-like bars */
  for (int i = 0; i < NX; i++)
    for (int j = 0; j < NY; j++)
      for (int k = 0; k < NZ; k++) {
        X[idx(i, j, k)][0] = 0.010 * i;
        X[idx(i, j, k)][1] = 0.008 * j;
        X[idx(i, j, k)][2] = 0.012 * k;
      }
  for (int a = 0; a < NN; a++)
    for (int b = a + 1; b < NN; b++) {
      int ia = a / (NY * NZ), ja = (a / NZ) % NY, ka = a % NZ;
      int ib = b / (NY * NZ), jb = (b / NZ) % NY, kb = b % NZ;
      if (abs(ia - ib) <= 1 && abs(ja - jb) <= 1 && abs(ka - kb) <= 1) bar(a, b, 2e7, 0.05);
    }
  for (int d = 0; d < NDOF; d++) M[d][d] += 1e-3;

  /* COO lower triangles and the maps */
  static int Kr[NDOF * NDOF], Kc[NDOF * NDOF], Mr[NDOF * NDOF], Mc[NDOF * NDOF];
  static double Kv[NDOF * NDOF], Mv[NDOF * NDOF];
  int64_t nk = 0, nm = 0;
  for (int r = 0; r < NDOF; r++)
    for (int c = 0; c <= r; c++) {
      if (K[r][c] != 0) { Kr[nk] = r + 1; Kc[nk] = c + 1; Kv[nk++] = K[r][c]; }
      if (M[r][c] != 0) { Mr[nm] = r + 1; Mc[nm] = c + 1; Mv[nm++] = M[r][c]; }
    }
  int dof_node[NDOF], dof_comp[NDOF], ids[NN], platform[NX * NZ], clamp[NX * NZ], np = 0, nc = 0;
  double xyz[3 * NN];
  for (int i = 0; i < NX; i++)
    for (int j = 0; j < NY; j++)
      for (int k = 0; k < NZ; k++) {
        int a = idx(i, j, k);
        ids[a] = node_id(i, j, k);
        for (int c = 0; c < 3; c++) {
          dof_node[3 * a + c] = ids[a];
          dof_comp[3 * a + c] = c + 1;
          xyz[3 * a + c] = X[a][c];
        }
        if (j == PLATFORM_J) platform[np++] = ids[a];
        if (j == 0) clamp[nc++] = ids[a];
      }
  double ref[3] = {0.005, 0.008 * PLATFORM_J, 0.006}, axis[3] = {0, 0, 2};
  double dir[3] = {1, 1, 0};
  int exc = node_id(1, NY - 2, 0);
  double a_unit[3] = {0, 0, 1}, d_unit[3] = {1 / sqrt(2.0), 1 / sqrt(2.0), 0};

  /* dense reference: q = [DOFs off the platform and root, u_R, theta] */
  int col_of[NDOF], nf = 0;
  for (int r = 0; r < NDOF; r++) {
    int a = r / 3, j = (a / NZ) % NY;
    col_of[r] = (j == PLATFORM_J || j == 0) ? -1 : nf++;
  }
  int nt = nf + 6;
  double *T = calloc((size_t)NDOF * nt, sizeof *T);
  for (int r = 0; r < NDOF; r++) {
    int a = r / 3, c = r % 3, j = (a / NZ) % NY;
    if (col_of[r] >= 0) T[(size_t)r * nt + col_of[r]] = 1;
    if (j != PLATFORM_J) continue;
    double rr[3] = {X[a][0] - ref[0], X[a][1] - ref[1], X[a][2] - ref[2]};
    T[(size_t)r * nt + nf + c] = 1;
    /* (theta x r)_c for theta = e_k */
    double ex[3][3] = {{0, -rr[2], rr[1]}, {rr[2], 0, -rr[0]}, {-rr[1], rr[0], 0}};
    for (int k = 0; k < 3; k++) T[(size_t)r * nt + nf + 3 + k] = ex[k][c];
  }
  double *Kt = calloc((size_t)nt * nt, sizeof *Kt), *Mt = calloc((size_t)nt * nt, sizeof *Mt);
  double *KT = calloc((size_t)NDOF * nt, sizeof *KT), *MT = calloc((size_t)NDOF * nt, sizeof *MT);
  for (int r = 0; r < NDOF; r++)
    for (int s = 0; s < NDOF; s++)
      for (int q = 0; q < nt; q++) {
        KT[(size_t)r * nt + q] += K[r][s] * T[(size_t)s * nt + q];
        MT[(size_t)r * nt + q] += M[r][s] * T[(size_t)s * nt + q];
      }
  for (int p = 0; p < nt; p++)
    for (int r = 0; r < NDOF; r++) {
      double t = T[(size_t)r * nt + p];
      if (t == 0) continue;
      for (int q = 0; q < nt; q++) {
        Kt[(size_t)p * nt + q] += t * KT[(size_t)r * nt + q];
        Mt[(size_t)p * nt + q] += t * MT[(size_t)r * nt + q];
      }
    }
  double *A = malloc(sizeof(double) * nt * nt), *B = malloc(sizeof(double) * nt * nt);
  double *w = malloc(sizeof(double) * nt), *work = malloc(sizeof(double) * 8 * nt);
  memcpy(A, Kt, sizeof(double) * nt * nt);
  memcpy(B, Mt, sizeof(double) * nt * nt);
  int one = 1, lwork = 8 * nt, info = 0;
  dsygv_(&one, "N", "U", &nt, A, &nt, B, &nt, w, work, &lwork, &info, 1, 1);
  check(info == 0, "dense reference dsygv");
  double fref[6];
  for (int k = 0; k < 6; k++) fref[k] = sqrt(w[k]) / (2 * PI);
  double f_max = 0.5 * (fref[2] + fref[3]) / 3; /* three modes in [0, 3 f_max] */

  /* the reduction */
  udmap_error err = udmap_new_error();
  udmap_reduction red = NULL;
  double srow[NDOF] = {0};
  srow[3 * idx(1, 5, 1) + 1] = 1e9; /* a "stress" proportional to one displacement */
  int st = udmap_reduce(err, NDOF, nk, Kr, Kc, Kv, nm, Mr, Mc, Mv, dof_node, dof_comp, NN, ids,
                        xyz, np, platform, ref, axis, exc, dir, nc, clamp, 1, srow, -1, f_max,
                        2, 1, &red);
  char msg[1024];
  udmap_get_error(err, msg, sizeof msg);
  if (st) printf("  %s\n", msg);
  check(st == UDMAP_OK && red != NULL, "udmap_reduce");
  if (!red) return 1;
  int r, nmod, ns, nff, g, e;
  check(udmap_reduction_sizes(err, red, &r, &nmod, &ns, &nff, &g, &e) == UDMAP_OK, "sizes");
  check(g == 1 && e == 7 && ns == 1 && nff == 3, "gamma_dof, exc_dof, rows, full freqs");
  check(r == 7 + nmod + 14 || r < 7 + nmod + 14, "r = 7 + modes + residual vectors");
  double *Mr_ = malloc(sizeof(double) * r * r), *Kr_ = malloc(sizeof(double) * r * r);
  double *sr = malloc(sizeof(double) * r), *fr = malloc(sizeof(double) * r), ff[3];
  check(udmap_reduction_get(err, red, Mr_, Kr_, sr, fr, ff) == UDMAP_OK, "get");
  for (int k = 0; k < 3; k++) {
    check_close(ff[k], fref[k], 1e-9, "full-model frequency (MUMPS + ARPACK) = dense");
    check_close(fr[k], fref[k], 1e-6, "reduced frequency = dense full model");
  }
  check(fr[3] > 3 * f_max, "next reduced frequency above the band");
  double infov[15];
  check(udmap_reduction_info(err, red, infov) == UDMAP_OK, "info");
  check(infov[2] == infov[3] && infov[4] == 3 && infov[5] == 3, "inertia counts");

  /* receptances of gamma: static and at 0.8 f_1, reduced vs dense (undamped, real) */
  for (int pass = 0; pass < 2; pass++) {
    double om2 = pass == 0 ? 0 : pow(2 * PI * 0.8 * fref[0], 2);
    double *Ad = malloc(sizeof(double) * nt * nt), *rhs = calloc(2 * nt, sizeof(double));
    for (int p = 0; p < nt * nt; p++) Ad[p] = Kt[p] - om2 * Mt[p];
    for (int k = 0; k < 3; k++) rhs[nf + 3 + k] = a_unit[k]; /* moment about a */
    /* force at E along d */
    for (int c = 0; c < 3; c++) {
      int row = 3 * idx(1, NY - 2, 0) + c;
      rhs[nt + col_of[row]] = d_unit[c];
    }
    int *ipiv = malloc(sizeof(int) * nt), two = 2;
    dgesv_(&nt, &two, Ad, &nt, ipiv, rhs, &nt, &info);
    double Hgg = 0, HgE = 0, sE = 0;
    for (int k = 0; k < 3; k++) {
      Hgg += a_unit[k] * rhs[nf + 3 + k];
      HgE += a_unit[k] * rhs[nt + nf + 3 + k];
    }
    for (int row = 0; row < NDOF; row++) {
      if (srow[row] == 0) continue;
      double u = 0; /* u = T q */
      for (int q = 0; q < nt; q++) u += T[(size_t)row * nt + q] * rhs[nt + q];
      sE += srow[row] * u;
    }
    double *Ar = malloc(sizeof(double) * r * r), *y = calloc(2 * r, sizeof(double));
    for (int p = 0; p < r * r; p++) Ar[p] = Kr_[p] - om2 * Mr_[p];
    y[g - 1] = 1;
    y[r + e - 1] = 1;
    int *ip2 = malloc(sizeof(int) * r);
    dgesv_(&r, &two, Ar, &r, ip2, y, &r, &info);
    double sEr = 0;
    for (int q = 0; q < r; q++) sEr += sr[q] * y[r + q];
    check_close(y[g - 1], Hgg, pass == 0 ? 1e-10 : 1e-6, "H_gg reduced = dense");
    check_close(y[r + g - 1], HgE, pass == 0 ? 1e-10 : 1e-6, "H_gE reduced = dense");
    check_close(sEr, sE, pass == 0 ? 1e-10 : 1e-6, "stress row reduced = dense");
    free(Ad); free(rhs); free(ipiv); free(Ar); free(y); free(ip2);
  }
  udmap_delete_reduction(&red);
  check(red == NULL, "delete sets NULL");

  /* bad input: status 2, the argument named, no handle */
  struct { const char *needle; int kind; } bad[] = {
      {"K: give the lower triangle", 0}, {"platform_nodes: the platform set is empty", 1},
      {"axis: the axis of gamma_P has zero length", 2}, {"exc_node: node 7 is not in the model", 3},
      {"clamp_nodes: node 5 is not in the model", 4}, {"dof_comp: components must be 1 to 6", 5},
      {"M: the mass matrix is not positive definite", 6}, {"n_modes/f_max", 7}};
  int off = 0; /* an entry below the diagonal */
  while (Kr[off] == Kc[off]) off++;
  for (size_t t = 0; t < sizeof bad / sizeof bad[0]; t++) {
    int kind = bad[t].kind, bad_clamp[1] = {5}, swap = Kr[off];
    double zero[3] = {0, 0, 0}, saved = 0;
    int64_t m_entry = 0;
    if (kind == 0) { Kr[off] = Kc[off]; Kc[off] = swap; }
    if (kind == 5) dof_comp[10] = 7;
    if (kind == 6) { /* one negative node mass off the platform */
      for (m_entry = 0; m_entry < nm; m_entry++)
        if (Mr[m_entry] == Mc[m_entry] && Mr[m_entry] == 3 * idx(1, 8, 1) + 1) break;
      saved = Mv[m_entry];
      Mv[m_entry] = -1.0;
    }
    red = (udmap_reduction)&bad; /* must come back NULL */
    st = udmap_reduce(err, NDOF, nk, Kr, Kc, Kv, nm, Mr, Mc, Mv, dof_node, dof_comp, NN, ids,
                      xyz, kind == 1 ? 0 : np, platform, ref, kind == 2 ? zero : axis,
                      kind == 3 ? 7 : exc, dir, kind == 4 ? 1 : nc, kind == 4 ? bad_clamp : clamp,
                      1, srow, -1, kind == 7 ? 0.0 : f_max, 2, 1, &red);
    udmap_get_error(err, msg, sizeof msg);
    int ok = st == UDMAP_EINPUT && strstr(msg, bad[t].needle) != NULL && red == NULL;
    if (!ok) printf("  status %d, message '%s', expected '%s'\n", st, msg, bad[t].needle);
    check(ok, bad[t].needle);
    if (kind == 0) { Kc[off] = Kr[off]; Kr[off] = swap; }
    if (kind == 5) dof_comp[10] = 2;
    if (kind == 6) Mv[m_entry] = saved;
  }
  udmap_delete_error(&err);
  free(T); free(Kt); free(Mt); free(KT); free(MT); free(A); free(B); free(w); free(work);
  free(Mr_); free(Kr_); free(sr); free(fr);
  return check_finish();
}
