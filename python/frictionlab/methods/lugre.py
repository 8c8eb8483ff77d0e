"""The LuGre output-error fit from Python: identify_lugre."""
from .. import _core

__all__ = ["identify_lugre"]


def identify_lugre(time, force, position, *, inertia, static_law=None, delta=2.0, stribeck_velocity=0.001,
                   substeps=4, max_iterations=50, axis="linear", vd=0.0):
    """LuGre sigma0 (N/m) and sigma1 (N s/m) by output error, with the static part (Fc, Fs, vs in
    m/s, sigma2) identified from the same record unless static_law (a FrictionLaw or its dict) is given.
    vd (m/s, >= 0): decay velocity of the damping sigma1 exp(-(v/vd)^2), held fixed; 0 = constant.
    A parameter the record cannot determine, or that ends at a bound, has std NaN and a warning.

    time (s), force (applied, N), position (m): 1-D arrays of equal length, the record starting at rest
    inertia: mass (kg, > 0). Returns a Result (parameters with std, fit of the position, law).
    Raises ValueError for a non-positive inertia or unequal lengths.
    """
    return _core._identify_lugre(time, force, position, inertia, static_law, delta, stribeck_velocity, substeps,
                                 max_iterations, axis, vd)
