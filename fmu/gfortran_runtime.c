/*
 * What the Linux FMU binary needs to link Debian 12's static GNU Fortran runtime
 * (libgfortran.a, GCC 12) into a shared object. That archive is compiled as PIE code, which a
 * shared object cannot hold in two places (fmu/CMakeLists.txt prepares the FMU's copy of it):
 *
 * - io/async.o writes its thread-local `thread_unit` with a local-exec TLS relocation. The
 *   copy leaves async.o out, and the routines below take its place as libgfortran itself
 *   defines them when it is built without threads (io/async.c with ASYNC_IO = 0): no
 *   asynchronous unit exists, every wait and queue operation has nothing to do. A unit becomes
 *   asynchronous only through OPEN(..., ASYNCHRONOUS='YES'), which the kernel never executes
 *   (tests/python/test_fmu_binary.py checks its sources), so init_async_unit is unreachable.
 * - io/unix.o reaches stdin, stdout and stderr PC-relative (an executable's copy relocations).
 *   The copy's references are renamed to the hidden pointers below, set to the C library's
 *   streams before any other constructor of the binary runs (priority 101).
 *
 * Same argument lists as libgfortran's (pointers and ints), with opaque pointer types.
 */
#include <stdbool.h>
#include <stdio.h>
#include <stdlib.h>

#define HIDDEN __attribute__((visibility("hidden")))

/* io/async.c: the unit of the calling I/O thread, read by runtime/error.c (initial-exec). */
HIDDEN __thread void *thread_unit = NULL;

HIDDEN void _gfortrani_init_async_unit(void *unit) {
  (void)unit;
  abort(); /* unreachable: see above */
}
HIDDEN void _gfortrani_enqueue_transfer(void *au, void *arg, int type) {
  (void)au, (void)arg, (void)type;
}
HIDDEN int _gfortrani_enqueue_done_id(void *au, int type) {
  (void)au, (void)type;
  return 0;
}
HIDDEN void _gfortrani_enqueue_done(void *au, int type) { (void)au, (void)type; }
HIDDEN void _gfortrani_enqueue_close(void *au) { (void)au; }
HIDDEN void _gfortrani_enqueue_data_transfer_init(void *au, void *dt, int read_flag) {
  (void)au, (void)dt, (void)read_flag;
}
HIDDEN bool _gfortrani_collect_async_errors(void *cmp, void *au) {
  (void)cmp, (void)au;
  return false;
}
HIDDEN bool _gfortrani_async_wait_id(void *cmp, void *au, int id) {
  (void)cmp, (void)au, (void)id;
  return false;
}
HIDDEN bool _gfortrani_async_wait(void *cmp, void *au) {
  (void)cmp, (void)au;
  return false;
}
HIDDEN void _gfortrani_async_close(void *au) { (void)au; }

/* io/unix.o's standard streams. */
HIDDEN FILE *udmap_gfortran_stdin, *udmap_gfortran_stdout, *udmap_gfortran_stderr;

__attribute__((constructor(101))) static void udmap_gfortran_streams(void) {
  udmap_gfortran_stdin = stdin;
  udmap_gfortran_stdout = stdout;
  udmap_gfortran_stderr = stderr;
}
