"""The parameter table for Python: udmap.case.SCHEMA's rows (FIELDS, TOP_LEVEL: keyword
arguments of udmap.case.Field), the flat names of the C structs, FMU variables and
plain arrays, the items of the FMU's case file and the ctypes structures of the C
structs of wrappers/c/udmap.h.

Generated from kernel/parameters.toml by cmake/generate_parameters.py: do not edit; edit the
table and run cmake/generate_parameters.py.
"""
import ctypes


#: The case-file fields in schema order: (section, kind, dotted name, Field keywords).
FIELDS = (
    ('blade', 'beam', 'E', dict(type='real', lo=1e6, hi=1e13, unit='Pa',
        doc="Young's modulus: elastomers to beyond diamond (1.2e12)")),
    ('blade', 'beam', 'rho', dict(type='real', lo=100.0, hi=30000.0, unit='kg/m3',
        doc='density: foams to beyond osmium (22600)')),
    ('blade', 'beam', 'zeta', dict(type='real', lo=0.0, hi=0.5,
        doc='damping ratio of the first bare-blade mode, up to half critical')),
    ('blade', 'beam', 'neck.L', dict(type='real', lo=0.0001, hi=3.0, unit='m',
        doc='neck length: micro-turbines to beyond the longest steam-turbine blades')),
    ('blade', 'beam', 'neck.h', dict(type='real', lo=1e-5, hi=1.0, unit='m',
        doc='neck section height (bending direction)')),
    ('blade', 'beam', 'neck.b', dict(type='real', lo=1e-5, hi=1.0, unit='m',
        doc='neck section width')),
    ('blade', 'beam', 'neck.elements', dict(type='int', lo=1, hi=1000,
        doc='neck beam elements (the first modes converge with a few)')),
    ('blade', 'beam', 'platform.L', dict(type='real', lo=1e-5, hi=1.0, unit='m',
        doc='platform length')),
    ('blade', 'beam', 'platform.m', dict(type='real', lo=1e-6, hi=1000.0, unit='kg',
        doc='platform mass: 1 mg to 1 t')),
    ('blade', 'beam', 'platform.J', dict(type='real', lo=1e-15, hi=100.0, unit='kg.m2',
        doc='platform rotary inertia about P: those masses at 30 um to 0.3 m')),
    ('blade', 'beam', 'airfoil.L', dict(type='real', lo=0.0001, hi=3.0, unit='m',
        doc='airfoil length')),
    ('blade', 'beam', 'airfoil.h', dict(type='real', lo=1e-5, hi=1.0, unit='m',
        doc='airfoil section height (bending direction)')),
    ('blade', 'beam', 'airfoil.b', dict(type='real', lo=1e-5, hi=1.0, unit='m',
        doc='airfoil section width')),
    ('blade', 'beam', 'airfoil.elements', dict(type='int', lo=2, hi=1000, even=True,
        doc='airfoil beam elements (even: E is a node)')),
    ('blade', 'matrices', 'M', dict(type='path', doc='mass matrix (Matrix Market)')),
    ('blade', 'matrices', 'K', dict(type='path', doc='stiffness matrix (Matrix Market)')),
    ('blade', 'matrices', 'C', dict(type='path', default='optional',
        doc='damping matrix (Matrix Market)')),
    ('blade', 'matrices', 'gamma_dof', dict(type='int', lo=1, hi=100000000,
        doc='DOF of the platform rotation (1-based)')),
    ('blade', 'matrices', 'exc_dof', dict(type='int', lo=1, hi=100000000,
        doc='DOF of the excitation (1-based)')),
    ('blade', 'matrices', 'u_dof', dict(type='int', lo=1, hi=100000000, default='optional',
        doc=("DOF of the platform's circumferential translation u_P (1-based; traveling "
         'waves)'))),
    ('blade', 'matrices', 'v_dof', dict(type='int', lo=1, hi=100000000, default='optional',
        doc="DOF of the platform's radial translation v_P (1-based; absent: held)")),
    ('blade', 'matrices', 'stress_K', dict(type='path', default='optional',
        doc='stress row, stiffness part')),
    ('blade', 'matrices', 'stress_M', dict(type='path', default='optional',
        doc='stress row, mass part')),
    ('blade', 'matrices', 'zeta', dict(type='real', lo=0.0, hi=0.5, default=0.0,
        doc='damping ratio of the first bare-blade mode')),
    ('damper', 'asymmetric', 'CF', dict(type='real', lo=0.001, hi=1e6, unit='N',
        doc='centrifugal load on the damper (real dampers: 10 N to 10 kN)')),
    ('damper', 'asymmetric', 'mu', dict(type='real', lo=0.0001, hi=10.0,
        doc=('friction coefficient (dry metals: 0.1 to 1.5; large values jam the damper: '
         'status 3)'))),
    ('damper', 'asymmetric', 'pitch', dict(type='real', lo=1e-6, hi=1.0, unit='m',
        doc='distance between the platform centres')),
    ('damper', 'asymmetric', 'y_P', dict(type='real', lo=-1.0, hi=1.0, unit='m',
        doc=('radial coordinate of the platform centres (damper geometry: within 1 m of its '
         'centre of gravity)'))),
    ('damper', 'asymmetric', 'beta_L_deg', dict(type='real', lo=0.0, hi=90.0, unit='deg',
        open=True, doc='left face inclination')),
    ('damper', 'asymmetric', 'beta_R_deg', dict(type='real', lo=0.0, hi=90.0, unit='deg',
        open=True, doc='right face inclination')),
    ('damper', 'asymmetric', 'flat_points', dict(type='points', lo=-1.0, hi=1.0, unit='m', count=2,
        doc='flat-side contact points')),
    ('damper', 'asymmetric', 'curved_point', dict(type='point', lo=-1.0, hi=1.0, unit='m',
        doc='curved-side contact point')),
    ('damper', 'asymmetric', 'kn_flat', dict(type='real', lo=100.0, hi=1e12, unit='N/m',
        doc='normal stiffness, flat side (soft polymer to stiffer than a 1 m steel cube)')),
    ('damper', 'asymmetric', 'kt_flat', dict(type='real', lo=100.0, hi=1e12, unit='N/m',
        doc='tangential stiffness, flat side')),
    ('damper', 'asymmetric', 'kn_curved', dict(type='real', lo=100.0, hi=1e12, unit='N/m',
        doc='normal stiffness, curved side')),
    ('damper', 'asymmetric', 'kt_curved', dict(type='real', lo=100.0, hi=1e12, unit='N/m',
        doc='tangential stiffness, curved side')),
    ('damper', 'jenkins', 'kt', dict(type='real', lo=1e-6, hi=1e12, unit='N.m/rad',
        doc='stuck stiffness (wide: non-dimensional models too)')),
    ('damper', 'jenkins', 'M_slip', dict(type='real', lo=1e-9, hi=1e9, unit='N.m',
        doc='slip moment')),
    ('damper', 'table', 'file', dict(type='path', doc='CSV gamma,k_re,k_im')),
    ('damper', 'table', 'delta_M', dict(type='real', lo=1e-12, hi=1e9, unit='N.m',
        default='optional', doc='moment swing for extrapolation')),
    ('analysis', None, 'f_min', dict(type='real', lo=0.001, hi=1e6, unit='Hz',
        doc=('lower edge of the band in which the resonance is sought (1 mHz: '
         'non-dimensional models)'))),
    ('analysis', None, 'f_max', dict(type='real', lo=0.001, hi=1e6, unit='Hz',
        doc='upper edge of the band')),
    ('analysis', None, 'sigma_all', dict(type='real', lo=1000.0, hi=1e10, unit='Pa', default=8e7,
        doc=("allowable alternating stress of the HCF check (up to beyond any material's "
         'strength)'))),
    ('analysis', None, 'rtol', dict(type='real', lo=1e-15, hi=0.001, default=1e-12,
        doc='relative tolerance of peak and root refinement (kernel limits, as below)')),
    ('analysis', None, 'grid_per_decade', dict(type='int', lo=2, hi=1000, default=24,
        doc='amplitude grid on which backbone roots are bracketed')),
    ('analysis', None, 'layers', dict(type='int', lo=4, hi=100000, default=200,
        doc='amplitude layers of the response curves (refined adaptively)')),
    ('analysis', None, 'eigen_method', dict(type='choice', default='auto',
        choices=('auto', 'direct', 'modal'),
        doc=('eigenvalue start: direct (zggev; ARPACK for large models) or modal (secular '
         'equation)'))),
    ('analysis', None, 'dense_max', dict(type='int', lo=1, hi=100000, default=200,
        doc='largest number of DOFs solved densely by zggev')),
    ('analysis', None, 'sweep_points', dict(type='int', lo=16, hi=1000000, default=400,
        doc='bare-blade frequency samples for bracketing curve crossings')),
    ('analysis', None, 'harmonics', dict(type='harmonics', lo=2, hi=64, default=1,
        doc='1, harmonics 0..H, or auto (PHYSICS.md 4.1)')),
    ('analysis', None, 'harmonic_tol', dict(type='real', lo=1e-10, hi=0.1, default=0.001,
        doc="relative change that stops harmonics auto (the kernel's limits)")),
    ('analysis', None, 'blades', dict(type='int', lo=2, hi=10000, default='optional',
        doc='blades N of the wheel, with engine_order (PHYSICS.md 2.6); excludes ibpa_deg')),
    ('analysis', None, 'engine_order', dict(type='int', lo=0, hi=1000000, default='optional',
        doc='engine order EO (taken modulo blades): interblade phase 2 pi EO/N; needs blades')),
    ('analysis', None, 'ibpa_deg', dict(type='real', lo=-360, hi=360, unit='deg', default=0.0,
        doc=('interblade phase angle phi (PHYSICS.md 2.6), 0 in phase; excludes '
         'blades/engine_order'))),
)
#: Top-level fields besides the sections: (name, Field keywords).
TOP_LEVEL = (
    ('name', dict(type='text', default='case', doc='case name')),
    ('description', dict(type='text', default='optional', doc='free text')),
)
#: The kernel's codes of the choice fields: (section, kind, name) -> {choice: code}.
CHOICE_CODES = {
    ('analysis', None, 'eigen_method'): {'auto': 0, 'direct': 1, 'modal': 2},
}
#: The flat names (C structs, FMU variables, plain arrays) of each section and kind:
#: (section, kind) -> ((flat name, dotted field name, indices of the coordinate), ...).
FLAT_NAMES = {
    ('blade', 'beam'): (('E', 'E', ()), ('rho', 'rho', ()), ('zeta', 'zeta', ()),
        ('neck_L', 'neck.L', ()), ('neck_h', 'neck.h', ()), ('neck_b', 'neck.b', ()),
        ('neck_elements', 'neck.elements', ()), ('platform_L', 'platform.L', ()),
        ('platform_m', 'platform.m', ()), ('platform_J', 'platform.J', ()),
        ('airfoil_L', 'airfoil.L', ()), ('airfoil_h', 'airfoil.h', ()),
        ('airfoil_b', 'airfoil.b', ()), ('airfoil_elements', 'airfoil.elements', ())),
    ('blade', 'matrices'): (('M', 'M', ()), ('K', 'K', ()), ('C', 'C', ()),
        ('gamma_dof', 'gamma_dof', ()), ('exc_dof', 'exc_dof', ()), ('u_dof', 'u_dof', ()),
        ('v_dof', 'v_dof', ()), ('stress_K', 'stress_K', ()), ('stress_M', 'stress_M', ()),
        ('zeta', 'zeta', ())),
    ('damper', 'asymmetric'): (('CF', 'CF', ()), ('mu', 'mu', ()), ('pitch', 'pitch', ()),
        ('y_P', 'y_P', ()), ('beta_L_deg', 'beta_L_deg', ()), ('beta_R_deg', 'beta_R_deg', ()),
        ('flat1_x', 'flat_points', (0, 0)), ('flat1_y', 'flat_points', (0, 1)),
        ('flat2_x', 'flat_points', (1, 0)), ('flat2_y', 'flat_points', (1, 1)),
        ('curved_x', 'curved_point', (0,)), ('curved_y', 'curved_point', (1,)),
        ('kn_flat', 'kn_flat', ()), ('kt_flat', 'kt_flat', ()), ('kn_curved', 'kn_curved', ()),
        ('kt_curved', 'kt_curved', ())),
    ('damper', 'jenkins'): (('kt', 'kt', ()), ('M_slip', 'M_slip', ())),
    ('damper', 'table'): (('file', 'file', ()), ('delta_M', 'delta_M', ())),
    ('analysis', None): (('f_min', 'f_min', ()), ('f_max', 'f_max', ()),
        ('sigma_all', 'sigma_all', ()), ('rtol', 'rtol', ()),
        ('grid_per_decade', 'grid_per_decade', ()), ('layers', 'layers', ()),
        ('eigen_method', 'eigen_method', ()), ('dense_max', 'dense_max', ()),
        ('sweep_points', 'sweep_points', ()), ('harmonics', 'harmonics', ()),
        ('harmonic_tol', 'harmonic_tol', ()), ('blades', 'blades', ()),
        ('engine_order', 'engine_order', ()), ('ibpa_deg', 'ibpa_deg', ())),
}
#: Items of the FMU's resources/udmap-case.txt (fmu/case.c): (section, kind) ->
#: ((name, type), ...).
CASE_ITEMS = {
    ('blade', 'matrices'): (('gamma_dof', 'int'), ('exc_dof', 'int'), ('u_dof', 'int'),
        ('v_dof', 'int')),
    ('damper', 'jenkins'): (('kt', 'real'), ('M_slip', 'real')),
    ('analysis', None): (('rtol', 'real'), ('grid_per_decade', 'int'), ('eigen_method', 'choice'),
        ('dense_max', 'int'), ('sweep_points', 'int'), ('harmonic_tol', 'real')),
}
#: FMU variables that only a blade or damper of this kind has (the others leave them out).
FMU_KIND_VARIABLES = {
    ('blade', 'beam'): ('neck_L', 'neck_h', 'neck_b', 'platform_L', 'platform_m', 'platform_J',
        'airfoil_L', 'airfoil_h', 'airfoil_b', 'neck_elements', 'airfoil_elements', 'E', 'rho'),
    ('damper', 'asymmetric'): ('mu', 'CF', 'kn_flat', 'kt_flat', 'kn_curved', 'kt_curved', 'pitch',
        'y_P', 'beta_L_deg', 'beta_R_deg', 'flat1_x', 'flat1_y', 'flat2_x', 'flat2_y', 'curved_x',
        'curved_y'),
}


class BeamParams(ctypes.Structure):
    """udmap_beam_params (wrappers/c/udmap.h)."""

    _fields_ = [
        ('E', ctypes.c_double),
        ('rho', ctypes.c_double),
        ('zeta', ctypes.c_double),
        ('neck_L', ctypes.c_double),
        ('neck_h', ctypes.c_double),
        ('neck_b', ctypes.c_double),
        ('platform_L', ctypes.c_double),
        ('platform_m', ctypes.c_double),
        ('platform_J', ctypes.c_double),
        ('airfoil_L', ctypes.c_double),
        ('airfoil_h', ctypes.c_double),
        ('airfoil_b', ctypes.c_double),
        ('neck_elements', ctypes.c_int),
        ('airfoil_elements', ctypes.c_int),
    ]


class AsymmetricParams(ctypes.Structure):
    """udmap_asymmetric_params (wrappers/c/udmap.h)."""

    _fields_ = [
        ('CF', ctypes.c_double),
        ('mu', ctypes.c_double),
        ('pitch', ctypes.c_double),
        ('y_P', ctypes.c_double),
        ('beta_L_deg', ctypes.c_double),
        ('beta_R_deg', ctypes.c_double),
        ('flat1_x', ctypes.c_double),
        ('flat1_y', ctypes.c_double),
        ('flat2_x', ctypes.c_double),
        ('flat2_y', ctypes.c_double),
        ('curved_x', ctypes.c_double),
        ('curved_y', ctypes.c_double),
        ('kn_flat', ctypes.c_double),
        ('kt_flat', ctypes.c_double),
        ('kn_curved', ctypes.c_double),
        ('kt_curved', ctypes.c_double),
    ]


class Analysis(ctypes.Structure):
    """udmap_analysis (wrappers/c/udmap.h)."""

    _fields_ = [
        ('f_min', ctypes.c_double),
        ('f_max', ctypes.c_double),
        ('sigma_all', ctypes.c_double),
        ('rtol', ctypes.c_double),
        ('grid_per_decade', ctypes.c_int),
        ('eigen_method', ctypes.c_int),
        ('dense_max', ctypes.c_int),
        ('sweep_points', ctypes.c_int),
        ('harmonics', ctypes.c_int),
        ('harmonic_tol', ctypes.c_double),
        ('ibpa_deg', ctypes.c_double),
    ]
