"""udmap: convergence-free mapping of underplatform damper-blade performance (Python API)."""
from ._lib import InputError, PhysicsError, UdmapError, version
from .damper import Damper

__all__ = ["Damper", "InputError", "PhysicsError", "UdmapError", "version"]
__version__ = version()
