"""Argument helpers shared by the identification methods' Python wrappers (frictionlab.methods)."""
import math
import os

import numpy as np

from . import _core


def _source(source):
    """(file, sha256) from a Data (load()), a path, or None."""
    if source is None:
        return "", ""
    if isinstance(source, (str, os.PathLike)):
        path = os.fspath(source)
        return path, _core.sha256_file(path)
    return getattr(source, "file", ""), getattr(source, "sha256", "")


def _nan(function, name, x):
    """An optional number option: None gives NaN (the library's "not given"); anything else must be
    a finite real number, or ArgumentTypeError / ValueError naming the argument."""
    if x is None:
        return math.nan
    if isinstance(x, (bool, str, bytes)) or not isinstance(x, (int, float, np.integer, np.floating)):
        raise _core.ArgumentTypeError(f"{function}: argument {name}: expected a number or None, got {type(x).__name__}")
    if not math.isfinite(x):
        raise ValueError(f"{function}: argument {name} is {x}; expected a finite number (or None)")
    return float(x)
