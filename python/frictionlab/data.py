"""Reading measured data files (CSV with a header row, MATLAB .mat) into numpy."""

from . import _core


class Data(dict):
    """The contents of a data file: a dict of column name -> 1-D numpy array (float64, in the
    file's units) and scalar name -> float (MAT 1x1 variables, e.g. ``gtau``).

    Attributes: ``file`` (the path as given), ``sha256`` (of the file's bytes; results carry it),
    ``columns`` (column names in file order), ``scalars`` (dict of the scalars), ``lines`` (CSV:
    the 1-based line of each sample; empty for MAT files).
    """

    def __init__(self, columns, scalars, file="", sha256="", lines=None):
        super().__init__()
        for name, values in columns:
            self[name] = values
        self.update(scalars)
        self.columns = [name for name, _ in columns]
        self.scalars = dict(scalars)
        self.file = file
        self.sha256 = sha256
        self.lines = lines

    def __missing__(self, key):
        where = f"{self.file}: " if self.file else ""
        contents = ", ".join(self.columns)
        if self.scalars:
            contents += " (scalars: " + ", ".join(self.scalars) + ")"
        raise KeyError(f"{where}no column '{key}'; the file has columns: {contents}")

    def __repr__(self):
        rows = len(self[self.columns[0]]) if self.columns else 0
        return (f"Data(file={self.file!r}, rows={rows}, columns={self.columns}, "
                f"scalars={self.scalars})")


def load(path, *, delimiter=",", drop_invalid=False, comment="#"):
    """Reads a data file by its extension: ``.csv`` (a header row of names, then numbers) or
    ``.mat`` (MATLAB v5 or v7.3; vectors become columns, 1x1 values scalars).

    Units are whatever the file holds; convert to SI with numpy (``d["q"] * 1e-3``).
    CSV options: ``delimiter`` (one character), ``drop_invalid`` (drop rows with empty or NaN
    cells instead of refusing the file), ``comment`` (lines starting with it are skipped; ''
    for none).

    Returns a :class:`Data` (a dict of numpy columns and float scalars, with ``file`` and
    ``sha256``). Raises ValueError naming the file, line and column on a bad file.
    """
    if not isinstance(delimiter, str) or not isinstance(comment, str):
        raise _core.ArgumentTypeError("load: arguments delimiter and comment: expected one character (str)")
    columns, scalars, file, sha256, lines = _core._load_dataset(path, delimiter, bool(drop_invalid), comment)
    return Data(columns, scalars, file, sha256, lines)
