"""Reading measured data files (CSV with or without a header row, MATLAB .mat) into numpy,
optionally resampled onto a uniform time grid."""
import math
import numbers

from . import _core


class Data(dict):
    """The contents of a data file: a dict of column name -> 1-D numpy array (float64, in the
    file's units) and scalar name -> float (MAT 1x1 variables, e.g. ``gtau``).

    Attributes: ``file`` (the path as given), ``sha256`` (of the file's bytes; results carry it),
    ``columns`` (column names in file order), ``scalars`` (dict of the scalars), ``lines`` (CSV:
    the 1-based line of each sample; empty for MAT files and after resampling),
    ``header_row`` (False for a CSV file without one: its columns are then ``names`` or c1, c2,
    ...), ``resampling`` (None, or after ``resample`` a dict of the record's jitter and the grid:
    ``dt_min``, ``dt_median``, ``dt_max``, ``dt``, ``max_gap`` in s, ``samples_in``,
    ``samples_out``, ``merged``), ``warnings`` (list of str: repeated time stamps merged, ...),
    ``unusable`` (MAT variables that are not columns, with what they are, e.g. "a 3x4 matrix").
    """

    def __init__(self, columns, scalars, file="", sha256="", lines=None, info=None):
        super().__init__()
        for name, values in columns:
            self[name] = values
        self.update(scalars)
        self.columns = [name for name, _ in columns]
        self.scalars = dict(scalars)
        self.file = file
        self.sha256 = sha256
        self.lines = lines
        info = info or {}
        self.header_row = info.get("header_row", True)
        self.resampling = info.get("resampling")
        self.warnings = list(info.get("warnings", []))
        self.unusable = dict(info.get("unusable", {}))
        self._contents = info.get("contents")

    def __missing__(self, key):
        where = f"{self.file}: " if self.file else ""
        contents = self._contents
        if contents is None:
            contents = ", ".join(self.columns)
            if self.scalars:
                contents += " (scalars: " + ", ".join(self.scalars) + ")"
        if key in self.unusable:
            rows = len(self[self.columns[0]]) if self.columns else 0
            raise KeyError(f"{where}variable '{key}' is {self.unusable[key]}; expected a real numeric vector "
                           f"(1xN or Nx1) of {rows} samples like the columns: {contents}")
        raise KeyError(f"{where}no column '{key}'; the file has columns: {contents}")

    def eval(self, expression):
        """The value of an expression of columns, as the command line's column options take it
        (``--force 'TorqueCur1 - Torque1'``): a new 1-D float64 array of the columns' length.

        The expression holds column and scalar names, numbers, ``+ - * /`` and parentheses; a
        name with spaces or operators goes between backquotes (```Torque cur [A]```). Columns
        are taken as they are in this dict now, so scale them first (``d["Torque1"] *= 1e-3``).
        Nothing is executed: names are only this data's columns and scalars.

        Raises ValueError naming the character of a syntax error, a missing column (with the
        file's columns) or the line of a non-finite sample; TypeError when ``expression`` is not
        a str.
        """
        if not isinstance(expression, str):
            raise TypeError(f"Data.eval: expression: expected a str, got {type(expression).__name__}")
        lines = [] if self.lines is None else [int(x) for x in self.lines]
        return _core._column_expression([(name, self[name]) for name in self.columns], self.scalars, self.file, lines,
                                        expression)

    def __repr__(self):
        rows = len(self[self.columns[0]]) if self.columns else 0
        return (f"Data(file={self.file!r}, rows={rows}, columns={self.columns}, "
                f"scalars={self.scalars})")


def _names_arg(names):
    if names is None:
        return []
    if isinstance(names, str):
        return names.split(",")
    try:
        out = list(names)
    except TypeError:
        raise TypeError(f"names: expected a list of column names or a comma-separated str, got "
                        f"{type(names).__name__}") from None
    for i, n in enumerate(out):
        if not isinstance(n, str):
            raise TypeError(f"names: name {i + 1} is {type(n).__name__} {n!r}; expected a str")
    return out


def _seconds_arg(value, name):
    if isinstance(value, bool) or not isinstance(value, numbers.Real) or not math.isfinite(value) or value <= 0:
        raise ValueError(f"{name} = {value!r}: expected a time in seconds, a finite number > 0")
    return float(value)


def load(path, names=None, resample=None, max_gap=None, *, time=None, delimiter=None, drop_invalid=False,
         comment="#", format="auto"):
    """Reads a data file by its extension: ``.csv``, ``.tsv`` or ``.txt`` (a text table) or ``.mat``
    (MATLAB v5 or v7.3; vectors become columns, 1x1 values scalars). ``format`` names the reader
    for a file whose name does not say (a robot's ``.log``): ``"csv"`` or ``"mat"``; ``"auto"``
    (default) goes by the extension. It is the command line's ``--format``.

    A CSV file may have a header row of names or none: a first row of numbers is data, and the
    columns are then named by ``names``, the others ``c1``, ``c2``, ... (1-based). The delimiter
    is detected (tab, ';', ',' or runs of blanks) unless ``delimiter`` is given; ``#`` comment
    lines, CRLF line ends, a UTF-8 byte order mark and quoted cells are accepted.

    ``names``: column names in file order (a list, or one comma-separated str). For a file
    without a header row they name its first columns; with a header row they replace the
    header's names the same way. More names than columns, an empty or repeated name is an error.

    ``resample``: None (default) leaves the samples as they are. True puts every column on a
    uniform time grid with the median step; a number is the grid step in s. Repeated time stamps
    are merged into their mean (with a warning); a gap longer than ``max_gap`` s (default 10
    median steps) is an error naming its rows, since interpolation would invent data there.
    The time column is ``time`` (default: the column 'time' if the file has one, else the
    first column). What resampling did is in ``.resampling``.

    Other CSV options: ``drop_invalid`` (drop rows with empty or NaN cells instead of refusing
    the file), ``comment`` (lines starting with it are skipped; '' for none).
    Units are whatever the file holds; convert to SI with numpy (``d["q"] * 1e-3``).

    Returns a :class:`Data`. Raises ValueError naming the file, line and column on a bad file,
    and the argument (``names``, ``resample``, ``max_gap``) on a bad one; TypeError for an
    argument of the wrong type.
    """
    name_list = _names_arg(names)
    do_resample = resample is not None and resample is not False
    dt = 0.0
    if do_resample and resample is not True:
        dt = _seconds_arg(resample, "resample")
    gap = 0.0
    if max_gap is not None:
        gap = _seconds_arg(max_gap, "max_gap")
        if not do_resample:
            raise ValueError(f"max_gap = {max_gap!r}: only used with resample (the gaps resampling may bridge)")
    if time is not None and not isinstance(time, str):
        raise TypeError(f"time: expected a column name (str), got {type(time).__name__}")
    if delimiter is None:
        delimiter = ""
    elif not isinstance(delimiter, str) or len(delimiter) != 1:
        raise ValueError(f"delimiter {delimiter!r}: expected one character, or None to detect it")
    if not isinstance(format, str):
        raise TypeError(f"format: expected 'csv', 'mat' or 'auto', got {type(format).__name__}")
    # The path goes to the extension as given: it names the argument when it is not a path.
    columns, scalars, file, sha256, lines, info = _core._load_dataset(
        path, delimiter, drop_invalid, comment, name_list, do_resample, dt, gap, time or "", format)
    return Data(columns, scalars, file, sha256, lines, info)
