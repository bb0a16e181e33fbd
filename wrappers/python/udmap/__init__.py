"""udmap: convergence-free mapping of underplatform damper-blade performance (Python API)."""
from ._capi import library_path, version
from .blade import Blade
from .damper import Damper
from .errors import InputError, PhysicsError, UdmapError
from .locate import fmu_path
from .model import Model

__all__ = ["Blade", "Damper", "Model", "InputError", "PhysicsError", "UdmapError", "version",
           "fmu_path", "library_path"]
__version__ = version()
