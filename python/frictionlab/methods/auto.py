"""Model selection from Python: identify_auto (every structure the record supports, chosen by
held-out error; frictionlab/identify/auto.hpp)."""
import json

from .. import _core
from .._args import _method_options, _source, _with_options_doc

__all__ = ["identify_auto"]


@_with_options_doc("auto")
def identify_auto(time, force, position=None, velocity=None, *, axis="linear", source=None, **options):
    """Model selection on held-out data. First says what experiment the record holds: a free decay
    (the force constant or unrelated to the motion while the axis oscillates) runs decay (Fc_over_k,
    zeta; Fc and Fv in force units with ``stiffness``, N/m or N m/rad, as identify_decay takes it);
    a slow ramp of force with stick runs breakaway (the trajectory candidates follow as
    runners-up); presliding gives the bristle stiffness
    sigma0 alone and names lugre; a coast-down is an error status with the reason. Otherwise it
    fits the inverse dynamic model with the Coulomb-viscous,
    Stribeck (vs searched) and asymmetric terms, and, when the record has constant-speed plateaus,
    a sweep's laws with M from the trajectory; answers with the candidate whose drive-force error
    on held-out time blocks (``folds``, default 4) or on a second record (``validate``: a dict
    with "time", "force" and "position" or "velocity") is lowest. Physically impossible fits
    (Fs below Fc, a negative Fc, Fv or M, vs <= 0) are refused.

    Arrays (1-D, equal length N, SI): ``time`` (s, regular), ``force`` (N or N m), ``position``
    (m or rad) or ``velocity`` (m/s or rad/s). Returns a Result (method auto); the candidates
    are in ``result.selection`` (a list of dicts: name, method, structure, status,
    heldout_error_percent, training_error_percent, block_errors_percent, reason, parameters)
    and ``result.diagnostics``.
    """
    values, inputs = _method_options("auto", "identify_auto", dict(options), stacklevel=3)
    file, sha = _source(source)
    r = _core._identify_auto(time, force, position, velocity, values, axis, file, sha, inputs.get("validate"))
    r._record_options(values)
    r.inputs = {"time": time, "force": force, "position": position, "velocity": velocity}
    r.selection = json.loads(r.to_json()).get("diagnostics", {}).get("selection", [])
    return r
