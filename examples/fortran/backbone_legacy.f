C     Blade A with its asymmetric damper through the plain-array API,
C     FORTRAN 77 style: no module, no derived type, parameters in arrays
C     in the order of the C structs udmap_beam_params and
C     udmap_asymmetric_params, an INFO code as in LAPACK.
C     Build: gfortran backbone_legacy.f $(pkg-config --libs udmap)
C     (or examples/fortran/CMakeLists.txt).
      PROGRAM BBLEG
      IMPLICIT NONE
      INTEGER NF, NG, MAXPTS
      PARAMETER (NF = 3, NG = 3, MAXPTS = 4000)
      DOUBLE PRECISION BEAM(14), DAMPER(16), ANALYS(2), FE(NF)
      DOUBLE PRECISION GAMMAP(NF), FRES(NF), SIGMAA(NF), UE(NF), FLIM
      DOUBLE PRECISION GAMMA(NG), KRE(NG), KIM(NG), BASE(6), FEXC
      DOUBLE PRECISION F(MAXPTS), GCURVE(MAXPTS), SCURVE(MAXPTS), GMAX
      INTEGER REGIME(NF), BRANCH(MAXPTS), NPTS, INFO, I, MAJOR, MINOR
      INTEGER PATCH
C     Blade: E, rho, zeta, neck L h b, platform L m J, airfoil L h b,
C     neck and airfoil elements
      DATA BEAM / 170D9, 8200D0, 0.002D0, 0.020D0, 0.008D0, 0.020D0,
     $            0.010D0, 0.021D0, 1.4D-6, 0.120D0, 0.004D0, 0.030D0,
     $            8D0, 24D0 /
C     Damper: CF, mu, pitch, y_P, beta_L, beta_R, flat1 x y, flat2 x y,
C     curved x y, kn_flat, kt_flat, kn_curved, kt_curved
      DATA DAMPER / 900D0, 0.3D0, 0.026D0, 0.006D0, 45D0, 45D0,
     $              -6.724D-3, -1.724D-3, -1.068D-3, 3.932D-3,
     $              3.268D-3, 1.768D-3, 60D6, 40D6, 80D6, 50D6 /
C     Band f_min, f_max [Hz]; the other settings keep their defaults
      DATA ANALYS / 150D0, 230D0 /
      DATA FE / 1D0, 2D0, 5D0 /
      DATA GAMMA / 1D-4, 5D-4, 2D-3 /
      DATA FEXC / 196D0 /
C
      CALL UDMAP_VERSION_NUMBERS(MAJOR, MINOR, PATCH)
      WRITE (*, '(A,I0,A,I0,A,I0,A)') 'udmap ', MAJOR, '.', MINOR, '.',
     $   PATCH, ', blade A'
C     Stiffness table k(gamma) of the damper and its base cycle
      CALL UDMAP_TABLE_ARRAYS(DAMPER, 16, NG, GAMMA, KRE, KIM, BASE,
     $                        INFO)
      IF (INFO .NE. 0) GO TO 900
      DO 10 I = 1, NG
         WRITE (*, '(A,3ES16.8)') 'table', GAMMA(I), KRE(I), KIM(I)
   10 CONTINUE
C     Backbone: the resonance peaks for the forces FE, and F_lim
      CALL UDMAP_BACKBONE_ARRAYS(BEAM, 14, DAMPER, 16, ANALYS, 2, NF,
     $     FE, GAMMAP, FRES, SIGMAA, UE, REGIME, FLIM, INFO)
      IF (INFO .NE. 0) GO TO 900
      WRITE (*, '(A,ES16.8,A)') 'F_lim = ', FLIM, ' N'
      WRITE (*, '(A)') '# F_E [N]  gamma_P [rad]  f_res [Hz]  sigma_a'
      DO 20 I = 1, NF
         WRITE (*, '(4ES16.8)') FE(I), GAMMAP(I), FRES(I), SIGMAA(I)
   20 CONTINUE
C     Response at the excitation frequency FEXC
      CALL UDMAP_RESPONSE_ARRAYS(BEAM, 14, DAMPER, 16, ANALYS, 2, FEXC,
     $     NF, FE, GAMMAP, SIGMAA, UE, REGIME, FLIM, INFO)
      IF (INFO .NE. 0) GO TO 900
      DO 30 I = 1, NF
         WRITE (*, '(A,4ES16.8)') 'response', FEXC, FE(I), GAMMAP(I),
     $      SIGMAA(I)
   30 CONTINUE
C     Response curve for F_E = 2 N with 200 amplitude layers
      CALL UDMAP_CURVE_ARRAYS(BEAM, 14, DAMPER, 16, ANALYS, 2, FE(2),
     $     200, MAXPTS, NPTS, F, GCURVE, SCURVE, BRANCH, INFO)
      IF (INFO .NE. 0) GO TO 900
      GMAX = 0D0
      DO 40 I = 1, NPTS
         GMAX = MAX(GMAX, GCURVE(I))
   40 CONTINUE
      WRITE (*, '(A,ES16.8,I8,ES16.8)') 'curve', FE(2), NPTS, GMAX
      GO TO 999
  900 WRITE (*, '(A,I0)') 'udmap failed, INFO = ', INFO
      STOP 1
  999 CONTINUE
      END
