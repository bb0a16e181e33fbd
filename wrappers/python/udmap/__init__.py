"""udmap: convergence-free mapping of underplatform damper-blade performance (Python API)."""
from ._lib import InputError, PhysicsError, UdmapError, version
from .blade import Blade
from .damper import Damper
from .model import Model

__all__ = ["Blade", "Damper", "Model", "InputError", "PhysicsError", "UdmapError", "version"]
__version__ = version()
