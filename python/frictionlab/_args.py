"""Argument helpers shared by the identification methods' Python wrappers (frictionlab.methods)."""
import math
import warnings
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


def _option_table(method):
    """The option table of ``method`` (a list of dicts: name, keyword, type, unit, default, help,
    expected, required, deprecated, applies), as the library declares it (frictionlab/identify/method.hpp)."""
    for m in _core._methods():
        if m["name"] == method:
            return m["options"]
    raise ValueError(f"identification method '{method}' is not known")


def _method_options(method, function, options, stacklevel=3):
    """The keyword options of a method function, checked against its option table.

    ``options`` holds the keywords as the caller wrote them. A former keyword (the table's
    ``deprecated``) still works, with a DeprecationWarning naming the keyword that replaces it (the
    command line's flag name), pointing at the user's call ``stacklevel`` frames up; an unknown
    keyword, the same option twice or a required one missing
    is a TypeError, as Python's own for a function's keywords. Returns (values, inputs): the
    checked OptionValues of the plain options (bad values raise ValueError naming the option), and
    {keyword: value} of the column and file options (arrays, laws, dicts) that the wrapper passes
    itself.
    """
    table = _option_table(method)
    by_keyword = {o["keyword"]: o for o in table}
    for o in table:
        for old in o["deprecated"]:
            by_keyword.setdefault(old, o)
    plain, inputs, seen = {}, {}, {}
    for keyword, value in options.items():
        o = by_keyword.get(keyword)
        if o is None:
            raise TypeError(f"{function}() got an unexpected keyword argument '{keyword}'; its options are "
                            f"{', '.join(x['keyword'] for x in table)}")
        if keyword != o["keyword"]:
            warnings.warn(f"{function}: keyword '{keyword}' is deprecated; use '{o['keyword']}' (the command line's "
                          f"--{o['name']})", DeprecationWarning, stacklevel=stacklevel)
        if o["keyword"] in seen:
            raise TypeError(f"{function}() got the option '{o['keyword']}' twice (as '{seen[o['keyword']]}' and "
                            f"'{keyword}')")
        seen[o["keyword"]] = keyword
        if o["type"] in ("column", "file"):
            inputs[o["keyword"]] = value
        else:
            plain[keyword] = value
    for o in table:
        if o["required"] and (o["keyword"] not in seen or
                              options.get(seen[o["keyword"]]) is None):
            raise TypeError(f"{function}() missing required keyword argument: '{o['keyword']}'")
    return _core._option_values(method, plain), inputs


def _options_doc(method):
    """The options part of a method function's docstring, from the option table."""
    lines = ["", "    Options (keyword: meaning [unit; default; when it applies]; from the option table, as the "
                 "command line's flags):"]
    for o in _option_table(method):
        # "applies with iv=True": the table's conditions in the words `frictionlab identify METHOD
        # --help` prints, keywords for flags (applies_text, identify/option_applies.hpp).
        notes = [x for x in (o["unit"], "required" if o["required"] else
                             (f"default {o['default']}" if o["default"] is not None else ""), o["applies"]) if x]
        lines.append(f"      {o['keyword']}: {o['help']}" + (f" [{'; '.join(notes)}]" if notes else ""))
        if o["deprecated"]:
            lines.append(f"        (formerly {', '.join(o['deprecated'])}: still accepted, deprecated)")
    return "\n".join(lines) + "\n"


def _with_options_doc(method):
    """Decorator: appends the option table of ``method`` to the function's docstring."""
    def wrap(f):
        f.__doc__ = (f.__doc__ or "") + _options_doc(method)
        return f
    return wrap
