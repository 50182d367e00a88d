"""seafast: sea-fastening response of long cargo (monopiles) on heavy-lift vessels.

Linear and nonlinear (harmonic balance with unilateral saddles) response of the cargo to the
vessel's hull-girder deflection and rigid-body motions in regular waves.
"""

__version__ = "0.1.0"

__all__ = ["__version__"]
