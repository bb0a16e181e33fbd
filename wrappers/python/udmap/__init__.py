"""udmap: convergence-free mapping of underplatform damper-blade performance (Python API)."""
from ._lib import InputError, PhysicsError, UdmapError, version
from .blade import Blade

__all__ = ["Blade", "InputError", "PhysicsError", "UdmapError", "version"]
__version__ = version()
