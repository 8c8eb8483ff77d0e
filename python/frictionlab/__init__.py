"""frictionlab: model, simulate and identify friction in motion systems.

SI units throughout: forces in N (N m on a rotary axis), velocities in m/s (rad/s).
Errors in input raise ValueError with the same message as the C++ library and the CLI.
"""

from ._core import FrictionLaw, __version__, law_names

__all__ = ["FrictionLaw", "law_names", "__version__"]
