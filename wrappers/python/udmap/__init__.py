"""udmap: convergence-free mapping of underplatform damper-blade performance (Python API)."""
from ._lib import InputError, PhysicsError, UdmapError, version

__all__ = ["InputError", "PhysicsError", "UdmapError", "version"]
__version__ = version()
