"""Batches at fleet scale: one identification per data file, many simulations (scenario lists,
Monte Carlo over seeds), and the drift of identified parameters over a fleet's logs, on Dask's
distributed scheduler or serially.

    import frictionlab as fl
    t = fl.batch.identify("logs/axis3/", "sweep", date_from="name")   # a LocalCluster of 2 workers
    t.to_csv("axis3.csv")
    d = fl.batch.drift(t, threshold=2.0)                              # flagged changes in d["flagged"]
    fl.plot.drift(d, file="axis3_drift.png")

Where it runs (``client``):
  "local" (default)  a dask.distributed LocalCluster started for the call and closed after it:
                     ``workers`` worker processes of one thread each (``processes=True``). Processes,
                     not threads: the C++ fits release the GIL, but reading a file, building the
                     arguments and the rows is Python that holds it, and a process keeps a crash
                     in one file's fit (an abort in the native code) to its worker. The cost is a
                     second or so to start the workers and pickling each row back (small dicts).
                     ``processes=False`` runs threads in this process instead (no start-up).
                     From a script, call it under ``if __name__ == "__main__":`` (the workers
                     import the script again); a call at a script's top level is refused at once
                     with a RuntimeError that shows the guard, rather than starting for ever.
  a Client           any ``dask.distributed.Client`` (a remote scheduler: ``Client("tcp://host:8786")``,
                     a dask-jobqueue or Kubernetes cluster's client). Its workers need frictionlab
                     importable (same version) and the data files at the same paths.
  None               serially in this process; dask is not imported (and need not be installed).
The rows do not depend on where they ran: each item is computed by the same function, alone.

How the items are sent (``chunk``): Dask costs a few ms per task (scheduling, pickling, the
round trip), more than one file's sweep fit (~2 ms), so the items go in chunks of consecutive
items, one task each, run one after another on the worker (``client=None``: checked, then unused):
  None (default)     automatic: about CHUNKS_PER_THREAD (4) chunks per worker thread of the
                     client (``sum(client.nthreads().values())`` when the call starts; a client
                     with no worker yet counts as one thread), at least 1 item per chunk: 400
                     files on 2 workers of one thread go as 8 chunks of 50.
  an int N >= 1      N items per chunk (the last one may be shorter); 1 is one task per item.
Chunks change neither the rows nor their order. An item's own failure stays its row; but a
worker lost while running a chunk (a crash in native code, killed for memory; Dask retries the
chunk on other workers and gives up when they die too) takes the whole chunk: each of its items
gets an error row "worker lost while running this job's chunk ...". Use ``chunk=1`` to keep such
a crash to its own item's row, or smaller chunks for items of very unequal cost (a chunk of
slow items then holds up the end less).

Every batch returns a :class:`Table`: one row per item in the order given, each a dict; a failed
item (a file that cannot be read, data that give no answer, a scenario that does not simulate) is
a row with ``status`` "error" and the ``message``, and never stops the others.
"""
import csv
import functools
import glob
import inspect
import io
import json
import logging
import math
import numbers
import os
import sys

import numpy as np

from . import _core

__all__ = ["Table", "data_files", "identify", "simulate", "drift", "log_date", "IDENTIFY_HEAD", "FIT_COLUMNS"]

#: The first columns of an identification table, in order (``date`` only with ``date_from``).
IDENTIFY_HEAD = ("index", "file", "date", "status", "message", "method", "model", "axis")
#: The fit columns after the parameters: the fit's relative error (percent), rmse with its unit,
#: the samples fitted; then the data file's SHA-256.
FIT_COLUMNS = ("relative_error_percent", "rmse", "rmse_unit", "samples", "sha256")

_DATA_EXTENSIONS = (".csv", ".mat")
#: Chunks per worker thread of the client when ``chunk`` is None: enough to keep every thread
#: busy to the end when chunks take unequal times, few enough that Dask's cost per task (a few
#: ms) is small against a chunk's work.
CHUNKS_PER_THREAD = 4


class Table:
    """Rows of a batch: a list of dicts with the same keys (``columns``, in order).

    ``len(t)``, ``t[i]`` (row i, a dict), ``t["Fc"]`` (a column as a numpy array: float64 for
    numbers, with NaN where a row has none; str otherwise), iteration over the rows.
    ``ok`` and ``failed``: the rows whose status is "ok" / "error".
    ``to_array()``: a numpy structured array; ``to_csv(path)``, ``to_json(path)``: files written
    atomically (an existing file only with ``overwrite=True``).
    """

    def __init__(self, rows, columns=None, kind="identify"):
        self.rows = list(rows)
        if columns is None:
            columns = []
            for r in self.rows:
                columns.extend(k for k in r if k not in columns)
        self.columns = list(columns)
        for r in self.rows:
            for c in self.columns:
                r.setdefault(c, None)
        self.kind = kind

    def __len__(self):
        return len(self.rows)

    def __iter__(self):
        return iter(self.rows)

    def __getitem__(self, key):
        if isinstance(key, str):
            if key not in self.columns:
                raise KeyError(f"batch table: no column '{key}'; the table has: {', '.join(self.columns)}")
            return self._column(key)
        return self.rows[key]

    def _column(self, name):
        values = [r[name] for r in self.rows]
        if all(v is None or isinstance(v, bool) for v in values) and any(isinstance(v, bool) for v in values):
            return np.array([bool(v) for v in values])
        if all(v is None or (isinstance(v, (int, float, np.number)) and not isinstance(v, bool)) for v in values):
            if name in ("index", "seed") and all(v is not None for v in values):
                return np.array(values, dtype=np.int64)
            return np.array([math.nan if v is None else float(v) for v in values], dtype=np.float64)
        return np.array(["" if v is None else str(v) for v in values])

    @property
    def ok(self):
        return [r for r in self.rows if r.get("status") == "ok"]

    @property
    def failed(self):
        """The rows whose status is not "ok" (none in a table without a status, as the drift table)."""
        if "status" not in self.columns:
            return []
        return [r for r in self.rows if r.get("status") != "ok"]

    def to_array(self):
        """The table as a numpy structured array: one field per column (float64, int64 for
        ``index`` and ``seed``, bool for flags, a unicode string of the longest cell otherwise)."""
        cols = [self._column(c) for c in self.columns]
        dtype = [(c, a.dtype if a.dtype.kind != "U" else f"U{max(1, a.dtype.itemsize // 4)}")
                 for c, a in zip(self.columns, cols)]
        out = np.zeros(len(self.rows), dtype=dtype)
        for c, a in zip(self.columns, cols):
            out[c] = a
        return out

    def csv_text(self):
        """The CSV text: a header row of the columns, then one line per row; numbers with 17
        significant digits (they read back exactly), an empty cell for a missing value or NaN."""
        buf = io.StringIO()
        w = csv.writer(buf, lineterminator="\n")
        w.writerow(self.columns)
        for r in self.rows:
            w.writerow([_cell(r[c]) for c in self.columns])
        return buf.getvalue()

    def json_text(self):
        """The JSON text: {"schema": 1, "kind": ..., "columns": [...], "rows": [{...}, ...]},
        NaN as null."""
        rows = [{c: _json_value(r[c]) for c in self.columns} for r in self.rows]
        return json.dumps({"schema": 1, "kind": self.kind, "columns": self.columns, "rows": rows}, indent=1,
                          allow_nan=False) + "\n"

    def to_csv(self, path, *, overwrite=False):
        """Writes csv_text() to ``path`` atomically (temporary file and rename). ValueError
        naming the path when it exists and ``overwrite`` is False."""
        _core._write_file_atomic(path, self.csv_text(), overwrite)

    def to_json(self, path, *, overwrite=False):
        """Writes json_text() to ``path`` atomically. ValueError when it exists and ``overwrite`` is False."""
        _core._write_file_atomic(path, self.json_text(), overwrite)

    def __repr__(self):
        # A table of items (identify, simulate) counts its ok and failed rows; a drift table has
        # no status (its rows are parameters of files that were identified) and counts the flagged.
        if "status" in self.columns:
            counts = f"{len(self.ok)} ok, {len(self.failed)} failed"
        elif "flagged" in self.columns:
            counts = f"{sum(1 for r in self.rows if r.get('flagged'))} flagged"
        else:
            counts = ""
        return f"Table({self.kind}: {len(self.rows)} rows{', ' + counts if counts else ''}; columns {self.columns})"


def _cell(v):
    if v is None:
        return ""
    if isinstance(v, bool):
        return "true" if v else "false"
    if isinstance(v, (float, np.floating)):
        return "" if not math.isfinite(v) else repr(float(v))
    return str(v)


def _json_value(v):
    if isinstance(v, (float, np.floating)):
        return float(v) if math.isfinite(v) else None
    if isinstance(v, np.integer):
        return int(v)
    return v


# ----------------------------------------------------------------------------------------------
# Where the items run


def _check_chunk(chunk):
    """ValueError naming ``chunk`` unless it is None (automatic) or a whole number >= 1."""
    if chunk is None:
        return
    if isinstance(chunk, bool) or not isinstance(chunk, numbers.Integral) or chunk < 1:
        raise ValueError(f"chunk = {chunk!r}: expected None (automatic: about {CHUNKS_PER_THREAD} chunks per "
                         "worker thread) or a whole number >= 1 of jobs per chunk")


def _chunk_size(chunk, n_jobs, n_threads):
    """Jobs per chunk: ``chunk`` when given; else n_jobs split into about CHUNKS_PER_THREAD chunks
    per worker thread (``n_threads``; a client with no worker yet counts as one), at least 1."""
    if chunk is not None:
        return int(chunk)
    return max(1, math.ceil(n_jobs / (CHUNKS_PER_THREAD * max(1, n_threads))))


GUARD_EXAMPLE = '''import frictionlab as fl

if __name__ == "__main__":   # worker processes import this script again: keep the batch under the guard
    t = fl.batch.identify(...)'''


def _guarded_main_call():
    """None when a LocalCluster of worker processes can start from here; else the line of the
    script (``__main__`` run from a file) that calls it outside ``if __name__ == "__main__":``.

    Dask starts worker processes by spawning a fresh interpreter, which imports the main script
    again: a batch called at the script's top level then starts again in every worker, which
    starts workers of its own, and the call never returns. Detected from the call stack: the
    script's module-level frame and whether its current line lies inside the guard (read from
    the script's source with ast). Interactive sessions, ``python -c`` and notebooks have no
    script file and are never refused."""
    import ast

    main = sys.modules.get("__main__")
    path = getattr(main, "__file__", None)
    if not path or not str(path).endswith(".py") or not os.path.isfile(path):
        return None
    frame = inspect.currentframe()
    line = None
    while frame is not None:
        if frame.f_code.co_name == "<module>" and frame.f_globals.get("__name__") in ("__main__", "__mp_main__") \
                and os.path.abspath(frame.f_code.co_filename) == os.path.abspath(path):
            line = frame.f_lineno
            break
        frame = frame.f_back
    if line is None:
        return None
    try:
        with open(path, encoding="utf-8") as f:
            tree = ast.parse(f.read(), path)
    except (OSError, SyntaxError, ValueError):
        return None

    def is_guard(node):
        if not isinstance(node, ast.If) or not isinstance(node.test, ast.Compare):
            return False
        sides = [node.test.left, *node.test.comparators]
        return any(isinstance(s, ast.Name) and s.id == "__name__" for s in sides) and \
            any(isinstance(s, ast.Constant) and s.value == "__main__" for s in sides)

    for node in tree.body:
        if is_guard(node) and node.lineno <= line <= (node.end_lineno or node.lineno):
            return None
    return f"{path}, line {line}"


def _run(function, jobs, client, workers, processes, chunk=None):
    """[function(job) for job in jobs], serially (client None), on a LocalCluster made here
    ("local"), or on the given Client, in chunks of jobs (see _run_on). ``function`` returns a
    row and never raises for an item's own failure. ``chunk`` is checked by the caller."""
    if client is None:
        return [function(job) for job in jobs]
    if isinstance(client, str):
        if client != "local":
            raise ValueError(f"client = {client!r}: expected 'local', None (serial) or a dask.distributed.Client")
        if isinstance(workers, bool) or not isinstance(workers, int) or workers < 1:
            raise ValueError(f"workers = {workers!r}: expected a whole number >= 1 of local workers")
        if processes:
            where = _guarded_main_call()
            if where is not None:
                raise RuntimeError(
                    f"frictionlab.batch: a LocalCluster of worker processes started at the top level of a script "
                    f"({where}): each worker imports the script again and would start the batch again, so the call "
                    f"would never return. Put the batch under the main guard:\n\n{GUARD_EXAMPLE}\n\n"
                    f"or run the workers as threads in this process (processes=False), or serially (client=None).")
        from distributed import Client, LocalCluster

        # silence_logs: the cluster's own log lines (a worker's "scheduler was unaware of this
        # worker" while it closes) are noise here; an item's failure is its row's message.
        with LocalCluster(n_workers=workers, threads_per_worker=1, processes=processes, dashboard_address=None,
                          silence_logs=logging.CRITICAL) as cluster, Client(cluster) as c:
            return _run_on(c, function, jobs, chunk)
    return _run_on(client, function, jobs, chunk)


def _run_chunk(function, jobs):
    """The rows of a chunk of jobs, in order (one Dask task)."""
    return [function(job) for job in jobs]


def _run_on(client, function, jobs, chunk):
    """The rows of ``jobs`` on ``client``: one Dask task per chunk of consecutive jobs (a task
    costs a few ms of scheduling and transfer, more than one file's fit), the chunks' rows
    joined in the jobs' order. A chunk whose worker is lost (KilledWorker: the worker died on it
    every time it was tried) gives an error row for each of its jobs."""
    from distributed import KilledWorker, wait

    size = _chunk_size(chunk, len(jobs), sum(client.nthreads().values()))
    chunks = [jobs[i:i + size] for i in range(0, len(jobs), size)]
    # pure=False: every chunk runs, even two equal ones (a Monte Carlo with a repeated seed).
    futures = client.map(functools.partial(_run_chunk, function), chunks, pure=False, key="frictionlab-batch")
    wait(futures)
    rows = []
    for part, f in zip(chunks, futures):
        try:
            rows.extend(f.result())
        except Exception as e:  # the whole chunk is lost: each of its jobs' rows says so
            what = (f"{len(part)} jobs, index {part[0]['head']['index']} to {part[-1]['head']['index']}"
                    if len(part) > 1 else "1 job")
            if isinstance(e, KilledWorker):
                message = f"worker lost while running this job's chunk ({what}): KilledWorker: {e}"
            else:
                message = f"worker failed on this job's chunk ({what}): {type(e).__name__}: {e}"
            rows.extend(_failed_job_row(job, message) for job in part)
    return rows


def _failed_job_row(job, message):
    return {**job["head"], "status": "error", "message": message}


# ----------------------------------------------------------------------------------------------
# One identification per data file


def data_files(data):
    """The data files of ``data``, in order: a folder (its .csv and .mat files, sorted by name;
    subfolders are not read), a glob pattern ("logs/axis3_*.csv", sorted), a file path, or a
    list of any of these (expanded in place, in the list's order). A path that does not exist is
    kept: its row will say so. ValueError when a folder or pattern gives no file, or nothing at all."""
    items = [data] if isinstance(data, (str, os.PathLike)) else list(data)
    files = []
    for item in items:
        if not isinstance(item, (str, os.PathLike)):
            raise TypeError(f"batch data: {item!r} is a {type(item).__name__}; expected a path, folder or glob (str)")
        p = os.fspath(item)
        if os.path.isdir(p):
            found = sorted(os.path.join(p, n) for n in os.listdir(p)
                           if n.lower().endswith(_DATA_EXTENSIONS) and os.path.isfile(os.path.join(p, n)))
            if not found:
                raise ValueError(f"batch data: folder {p} has no .csv or .mat file")
            files.extend(found)
        elif glob.has_magic(p):
            found = sorted(glob.glob(p))
            if not found:
                raise ValueError(f"batch data: pattern {p} matches no file")
            files.extend(found)
        else:
            files.append(p)
    if not files:
        raise ValueError("batch data: no data files given")
    return files


def log_date(path, date_from="name", data=None):
    """The date a log was taken, as (iso, posix_seconds), or None when there is none.

    ``date_from``: "name" (the last date in the file's base name: YYYY-MM-DD, YYYY_MM_DD or
    YYYYMMDD, optionally followed by a time HH:MM[:SS], HH-MM[-SS] or HHMM[SS] after 'T', '_',
    '-' or ' ': "axis3_2026-11-02.csv", "log-20261102T0815.mat"); or "column:NAME" (the first
    value of column NAME of ``data``, or scalar NAME of a MAT file: POSIX time in s since
    1970-01-01 UTC). ISO dates are UTC: "YYYY-MM-DD" or "YYYY-MM-DDTHH:MM:SS"."""
    if date_from == "name":
        return _core._log_date_from_name(os.fspath(path))
    if isinstance(date_from, str) and date_from.startswith("column:") and len(date_from) > 7:
        name = date_from[7:]
        if data is None:
            raise ValueError(f"date_from {date_from!r}: needs the file's data")
        v = data[name]  # KeyError naming the file and its columns
        first = float(np.ravel(v)[0]) if np.ndim(v) else float(v)
        return _core._log_date_from_posix(first)
    raise ValueError(f"date_from = {date_from!r}: expected 'name' or 'column:NAME'")


def _method_function(method):
    from .identify import METHOD_FUNCTIONS, methods

    for m in methods():
        if m.name == method and m.function and m.function in METHOD_FUNCTIONS:
            return m.function, METHOD_FUNCTIONS[m.function]
    names = [m.name for m in methods() if m.function and m.name != "validate"]
    raise ValueError(f"batch identify: method '{method}': expected one of {', '.join(names)}")


def _array_arguments(function):
    """(required, optional) array argument names of an identify function: its positional
    parameters (the arrays come before the '*')."""
    required, optional = [], []
    for p in inspect.signature(function).parameters.values():
        if p.kind is not p.POSITIONAL_OR_KEYWORD:
            continue
        (required if p.default is p.empty else optional).append(p.name)
    return required, optional


def _arrays(data, function, columns):
    """The identify function's arrays from a file's Data: ``columns`` is None (each array from
    the column of its own name: time, force, velocity, position; of idim's position and velocity
    the first the file has), a dict {argument: column name}, or a function Data -> {argument: array}."""
    if callable(columns):
        return dict(columns(data))
    required, optional = _array_arguments(function)
    mapping = dict(columns or {})
    unknown = [k for k in mapping if k not in required + optional]
    if unknown:
        raise ValueError(f"columns: '{unknown[0]}' is not an array of this method; expected "
                         f"{', '.join(required + optional)}")
    out = {arg: data[mapping.get(arg, arg)] for arg in required}
    given_optional = [a for a in optional if a in mapping]
    if given_optional:
        out.update({a: data[mapping[a]] for a in given_optional})
    else:
        for a in optional:
            if a in data.columns:
                out[a] = data[a]
                break
    return out


def _row_of_result(head, r):
    row = dict(head)
    row.update(status=r.status, message=r.message, method=r.method, model=r.model, axis=r.axis)
    for p in r.parameters.values():
        row[p.name] = p.value
        row[f"{p.name}_std"] = p.std
        row[f"{p.name}_unit"] = p.unit
    row.update(relative_error_percent=r.fit.relative_error_percent, rmse=r.fit.rmse, rmse_unit=r.fit.unit,
               samples=r.fit.samples, sha256=r.data_sha256)
    return row


def _message(e):
    """An item's error as its row's message: the library's own message for bad input (ValueError,
    KeyError, TypeError, OSError, RuntimeError), the exception's type and text for anything else."""
    if isinstance(e, KeyError) and e.args:
        return str(e.args[0])
    if isinstance(e, (ValueError, TypeError, OSError, RuntimeError)):
        return str(e)
    return f"internal error: {type(e).__name__}: {e}"


def _identify_job(job):
    """One file's row (runs on a worker). Never raises: a failure is the row's message."""
    head = dict(job["head"])
    try:
        from .data import load

        d = load(head["file"], **job["load"])
        if job["date_from"] is not None:
            date = log_date(head["file"], job["date_from"], d)
            if date is None:
                raise ValueError(f"{head['file']}: no date in the file's name; expected e.g. name_2026-11-02.csv "
                                 "(YYYY-MM-DD, YYYYMMDD, optionally with a time)")
            head["date"] = date[0]
        _, function = _method_function(job["method"])
        arrays = _arrays(d, function, job["columns"])
        options = dict(job["options"])
        if "source" in inspect.signature(function).parameters:
            options["source"] = d
        r = function(**arrays, **options)
        return _row_of_result(head, r)
    except Exception as e:  # noqa: BLE001 - one file's failure, whatever it is, is its row's
        return {**head, "status": "error", "message": _message(e), "method": job["method"]}


def identify(data, method, *, columns=None, load=None, date_from=None, client="local", workers=2, processes=True,
             chunk=None, **options):
    """One identification per data file, one row per file.

    ``data``: a folder, a glob pattern, a file, or a list of them (see data_files).
    ``method``: "idim", "breakaway", "sweep", "decay" or "lugre"; ``**options``: the method's
    options as its function takes them (``identify_sweep(model="coulomb-viscous")`` ->
    ``identify(..., "sweep", model="coulomb-viscous")``; lugre's ``inertia`` is required).
    ``columns``: which file columns are the method's arrays: None (the column of each array's
    own name: time, force, velocity, position), a dict {argument: column name}
    ({"force": "torque"}), or a function Data -> {argument: numpy array} for derived signals
    (``lambda d: {"time": d["t"], "force": d["gtau"] * d["vir"], "position": d["qm"]}``; Dask
    ships it to the workers with cloudpickle, so a lambda will do).
    ``load``: options of frictionlab.load for every file (``{"resample": True}``, ``names``, ...).
    ``date_from``: None, "name" or "column:NAME": adds a ``date`` column (see log_date); a file
    without one is an error row.
    ``client``, ``workers``, ``processes``: where it runs; ``chunk``: files per Dask task (None:
    automatic, about 4 tasks per worker thread; see the module's doc).

    Returns a :class:`Table`: columns ``index`` (the file's place in data_files(data), from 0),
    ``file``, ``date`` (with date_from), ``status`` ("ok"/"error"), ``message``, ``method``,
    ``model``, ``axis``, then for each parameter P: ``P`` (value), ``P_std``, ``P_unit`` (SI:
    N, N s/m, ... or N m, N m s/rad, ...), then ``relative_error_percent`` (percent), ``rmse``
    (in ``rmse_unit``), ``samples`` and ``sha256`` (of the file). Parameters are in the order
    the first ok row has them. ValueError for a bad method, data, client or chunk argument (before any work).
    """
    _check_chunk(chunk)
    files = data_files(data)
    function_name, _ = _method_function(method)
    if load is not None and not isinstance(load, dict):
        raise TypeError(f"load: expected a dict of frictionlab.load options, got {type(load).__name__}")
    if date_from is not None and date_from != "name" and not (isinstance(date_from, str) and date_from.startswith("column:")):
        raise ValueError(f"date_from = {date_from!r}: expected None, 'name' or 'column:NAME'")
    jobs = []
    for i, f in enumerate(files):
        head = {"index": i, "file": f}
        if date_from is not None:
            head["date"] = ""
        jobs.append({"head": head, "method": method, "columns": columns, "load": dict(load or {}),
                     "options": options, "date_from": date_from})
    rows = _run(_identify_job, jobs, client, workers, processes, chunk)
    return Table(rows, _identify_columns(rows, date_from is not None), kind="identify")


def _identify_columns(rows, with_date):
    head = [c for c in IDENTIFY_HEAD if with_date or c != "date"]
    params = []
    for r in rows:
        for k in r:
            if k not in head and k not in FIT_COLUMNS and k not in params:
                params.append(k)
    return head + params + list(FIT_COLUMNS)


# ----------------------------------------------------------------------------------------------
# Many simulations


def _default_summary(tr):
    """What a simulation row holds by default: the final state, the largest speed, the
    mode-switch counts and the solver's work."""
    v = np.asarray(tr["velocity"])
    kinds = [s["kind"] for s in tr.switches]
    stats = tr.stats
    return {"final_time": float(tr["time"][-1]), "final_position": float(tr["position"][-1]),
            "final_velocity": float(v[-1]), "max_abs_velocity": float(np.max(np.abs(v))),
            "breakaways": kinds.count("breakaway"), "sticks": kinds.count("stick"),
            "steps": int(stats["steps"])}


def _simulate_job(job):
    head = dict(job["head"])
    try:
        from .simulate import simulate as run_one

        scenario = job["scenario"]
        if job["make"] is not None:
            scenario = job["make"](head["seed"])
        tr = run_one(scenario, **job["overrides"])
        summary = job["summary"] or _default_summary
        return {**head, "status": "ok", "message": "", **dict(summary(tr))}
    except Exception as e:  # noqa: BLE001 - one scenario's failure is its row's
        return {**head, "status": "error", "message": _message(e)}


def simulate(scenarios=None, *, make=None, seeds=None, summary=None, client="local", workers=2, processes=True,
             chunk=None, **overrides):
    """Many simulations, one row each: a list of scenarios (files or dicts, as frictionlab.simulate
    takes them), or a Monte Carlo: ``make(seed) -> scenario`` for each seed of ``seeds`` (draw the
    perturbed parameters from ``numpy.random.default_rng(seed)`` inside ``make``: the rows then
    do not depend on where or in which order they ran).
    ``summary``: a function Trajectory -> dict of numbers for each row (default: final_time s,
    final_position m or rad, final_velocity and max_abs_velocity m/s or rad/s, breakaways,
    sticks, steps). ``**overrides``: frictionlab.simulate's law, duration, output_rate.
    ``client``, ``workers``, ``processes``, ``chunk`` (simulations per Dask task): as for identify.
    Returns a :class:`Table`: ``index``, ``scenario`` (the file, or "#i" for a dict), ``seed``
    (Monte Carlo), ``status``, ``message``, then the summary's keys. ValueError for bad
    scenarios/make/seeds, client or chunk arguments (before any work).
    """
    _check_chunk(chunk)
    if (scenarios is None) == (make is None):
        raise ValueError("batch simulate: give scenarios (a list) or make (a function of the seed) with seeds")
    jobs = []
    if make is not None:
        if seeds is None:
            raise ValueError("batch simulate: make needs seeds (e.g. range(100))")
        for i, seed in enumerate(seeds):
            jobs.append({"head": {"index": i, "scenario": f"#{i}", "seed": int(seed)}, "scenario": None,
                         "make": make, "summary": summary, "overrides": overrides})
    else:
        if isinstance(scenarios, (str, os.PathLike, dict)):
            scenarios = [scenarios]
        for i, sc in enumerate(scenarios):
            name = os.fspath(sc) if isinstance(sc, (str, os.PathLike)) else f"#{i}"
            jobs.append({"head": {"index": i, "scenario": name}, "scenario": sc, "make": None, "summary": summary,
                         "overrides": overrides})
    if not jobs:
        raise ValueError("batch simulate: no scenarios")
    rows = _run(_simulate_job, jobs, client, workers, processes, chunk)
    return Table(rows, kind="simulate")


# ----------------------------------------------------------------------------------------------
# Fleet drift


#: The columns of a drift table.
DRIFT_COLUMNS = ("file", "date", "parameter", "value", "std", "unit", "change", "combined_std", "flagged")


def drift(table, parameters=None, *, threshold=1.0):
    """The drift table of an identification batch with dates (``identify(..., date_from=...)``,
    or rows with ``date`` in ISO form "YYYY-MM-DD[THH:MM:SS]"): for each parameter (``parameters``:
    names, default all of the table's), its ok rows in date order, each with its ``change`` from
    the previous log (unit of the parameter), the ``combined_std`` sqrt(std^2 + previous std^2)
    and ``flagged`` = |change| > threshold * combined_std.

    The rule is the simple condition-monitoring one: a change larger than the estimates'
    combined uncertainty. With no real change and independent normal errors, threshold 1 (the
    default) flags about 32 % of pairs, 2 about 4.6 %, 3 about 0.3 %: use 2 or 3 for a fleet.
    A parameter without a std (null) is never flagged. Error rows are left out.
    Returns a :class:`Table` of DRIFT_COLUMNS (kind "drift").
    """
    rows = table.rows if isinstance(table, Table) else list(table) if isinstance(table, (list, tuple)) else None
    if rows is None or not all(isinstance(r, dict) for r in rows):
        raise TypeError(f"drift: table: expected a Table of identify() or a list of row dicts, got "
                        f"{type(table).__name__}")
    samples = []
    for r in rows:
        if r.get("status", "ok") != "ok":
            continue
        date = r.get("date")
        if not date:
            raise ValueError(f"drift: {r.get('file', '?')}: no date; run identify with date_from='name' or "
                             "'column:NAME'")
        posix = _iso_posix(date, r.get("file", "?"))
        names = parameters or [k[:-5] for k in r if k.endswith("_unit") and k != "rmse_unit"]
        for p in names:
            if p not in r or r[p] is None:
                if parameters:
                    raise ValueError(f"drift: {r.get('file', '?')}: no parameter '{p}'")
                continue
            sd = r.get(f"{p}_std")
            samples.append((str(r.get("file", "")), date, posix, p, float(r[p]),
                            math.nan if sd is None else float(sd), str(r.get(f"{p}_unit", ""))))
    out = _core._drift_table(samples, float(threshold))
    return Table(out, list(DRIFT_COLUMNS), kind="drift")


def _iso_posix(iso, file):
    """POSIX seconds of an ISO date from log_date (the library's own parse, so both agree)."""
    d = _core._log_date_from_name(str(iso).replace(":", "-"))
    if d is None:
        raise ValueError(f"drift: {file}: date {iso!r}: expected YYYY-MM-DD or YYYY-MM-DDTHH:MM:SS")
    return d[1]
