"""frictionlab: model, simulate and identify friction in motion systems.

SI units throughout: forces in N (N m on a rotary axis), velocities in m/s (rad/s), positions
in m (rad), inertia in kg (kg m^2), time in s. Errors in input raise ValueError with the same
message as the C++ library and the command line, naming the function and the argument; an
argument of the wrong type (None, a string, an object or complex array) raises
ArgumentTypeError, which is both a TypeError and a ValueError. Bad input that the library gives a
code (a data file's missing column, a scenario's unknown key, ...) raises frictionlab.Error, a
ValueError with .code (e.g. "data.column_missing") and the fields that apply (.file, .row,
.column, .key, .option, .value; None otherwise). A failed integration raises RuntimeError.

    import frictionlab as fl
    d = fl.load("DATA_EMPS.mat")                       # dict of numpy columns and scalars
    r = fl.identify_idim(d["t"], d["gtau"] * d["vir"], position=d["qm"], source=d)
    print(r)                                           # parameter table
    tr = fl.simulate("examples/craig_motor_trapezoid.yaml")
    fl.plot.simulation(tr, file="trapezoid.png")

Plotting helpers (matplotlib) are in frictionlab.plot, imported on first use. Batches (one
identification per file of a folder, many simulations, the drift of a fleet's parameters) are in
frictionlab.batch, on Dask's distributed scheduler or serially.
"""

from ._core import (
    ArgumentTypeError,
    BreakawayOptions,
    ContourResult,
    DecayOptions,
    Diagnostics,
    Error,
    EnvelopeFit,
    EnvelopeOptions,
    EnvelopeResult,
    FitFigures,
    FrictionLaw,
    IdimOptions,
    Parameter,
    Result,
    Scenario,
    StaticFit,
    StaticFitOptions,
    StickSlipOptions,
    StickSlipResult,
    SweepOptions,
    Trajectory,
    ValidationFigures,
    __version__,
    analyze_contour,
    budget_factor,
    export_c,
    export_mjcf,
    law_names,
    load_law,
    set_budget_factor,
    sha256_file,
)
from . import batch  # imports dask only when a batch runs on it
from .analysis import analyze_map, decay_envelope, detect_stick_slip
from .data import Data, load
# Each identification method's functions come from its module, frictionlab/methods/NAME.py, for
# every method of the library's table (see frictionlab.identify): nothing here names them.
from .identify import METHOD_FUNCTIONS as _METHOD_FUNCTIONS
from .identify import fit_static_law, methods
from .plan import plan
from .simulate import simulate

globals().update(_METHOD_FUNCTIONS)

__all__ = [
    "ArgumentTypeError", "BreakawayOptions", "ContourResult", "Data", "DecayOptions", "Diagnostics", "Error", "EnvelopeFit", "EnvelopeOptions", "EnvelopeResult",
    "FitFigures", "FrictionLaw", "IdimOptions", "Parameter", "Result", "Scenario", "StaticFit", "StaticFitOptions",
    "StickSlipOptions", "StickSlipResult", "SweepOptions", "Trajectory", "ValidationFigures", "__version__",
    "analyze_contour", "analyze_map", "budget_factor", "decay_envelope", "detect_stick_slip", "export_c", "export_mjcf", "fit_static_law", "law_names", "load",
    "load_law", "methods", "plan", "set_budget_factor", "sha256_file", "simulate", *_METHOD_FUNCTIONS,
]


def __getattr__(name):
    # `frictionlab.plot` imports matplotlib only when asked for.
    if name == "plot":
        import importlib

        return importlib.import_module(".plot", __name__)
    raise AttributeError(f"module 'frictionlab' has no attribute '{name}'")
