"""The LuGre output-error fit from Python: identify_lugre."""
from .. import _core
from .._args import _method_options, _with_options_doc

__all__ = ["identify_lugre"]


@_with_options_doc("lugre")
def identify_lugre(time, force, position, *, axis="linear", **options):
    """LuGre sigma0 (N/m) and sigma1 (N s/m) by output error, with the static part (Fc, Fs, vs in
    m/s, sigma2) identified from the same record unless ``static`` (a FrictionLaw or its dict) is
    given. A parameter the record cannot determine, or that ends at a bound, has std NaN and a
    warning.

    time (s), force (applied, N), position (m): 1-D arrays of equal length, the record starting at
    rest; ``inertia`` (kg, > 0) is required. Returns a Result (parameters with std, fit of the
    position, law). Raises ValueError for a non-positive inertia or unequal lengths.
    """
    values, inputs = _method_options("lugre", "identify_lugre", options)
    r = _core._identify_lugre(time, force, position, values, inputs.get("static"), axis)
    r._record_options(values)
    return r
