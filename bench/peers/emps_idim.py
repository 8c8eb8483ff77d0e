#!/usr/bin/python3
"""Peer: the EMPS IDIM-LS pipeline (Janot, Gautier, Brunot 2019 recipe, as tests/peers/
emps_idim_reference.py) with scipy.io.loadmat, scipy.signal (butter + filtfilt, decimate) and
numpy (gradient, linalg.lstsq): read DATA_EMPS.mat, filter, differentiate, decimate, solve,
standard deviations, then the cross-test on DATA_EMPS_PULSES.mat. Timed end to end (seconds)
and on the two files already in memory (compute_seconds).

Usage: emps_idim.py [--repeat N] [--once]
Prints JSON {task, seconds (best of N), compute_seconds, parameters {M, Fv, Fc, offset}, std, relative_error_percent,
cross_test_percent, accuracy: relative error of each parameter against the published IDIM-LS}."""
import argparse
import os

import numpy as np
import scipy.io
import scipy.signal as sg

from common import SOURCE, best_of, emit

DATA = os.path.join(SOURCE, "data", "emps")
NAMES = ["M", "Fv", "Fc", "offset"]
PUBLISHED = {"M": 95.1089, "Fv": 203.5034, "Fc": 20.3935, "offset": -3.1648}


def load(fname):
    return scipy.io.loadmat(os.path.join(DATA, fname))


def regression(m):
    t, qm, vir, gtau = m["t"].ravel(), m["qm"].ravel(), m["vir"].ravel(), float(m["gtau"].ravel()[0])
    dt = (t[-1] - t[0]) / (len(t) - 1)
    b, a = sg.butter(4, 100 / (0.5 / dt))
    qf = sg.filtfilt(b, a, qm, padtype="odd", padlen=12)
    qd = np.gradient(qf, dt)
    qdd = np.gradient(qd, dt)
    X = np.column_stack([qdd, qd, np.sign(qd), np.ones_like(qd)])[49:]
    y = (gtau * vir)[49:]
    return sg.decimate(X, 10, axis=0), sg.decimate(y, 10)


def pipeline(files=None):
    """The recipe; files: the two loaded .mat dictionaries, or None to read them here."""
    ident, pulses = files if files is not None else (load("DATA_EMPS.mat"), load("DATA_EMPS_PULSES.mat"))
    X, y = regression(ident)
    th, *_ = np.linalg.lstsq(X, y, rcond=None)
    e = y - X @ th
    s2 = e @ e / (len(y) - X.shape[1])
    std = np.sqrt(s2 * np.diag(np.linalg.inv(X.T @ X)))
    X2, y2 = regression(pulses)
    e2 = y2 - X2 @ th
    return th, std, 100 * np.linalg.norm(e) / np.linalg.norm(y), 100 * np.linalg.norm(e2) / np.linalg.norm(y2)


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("--repeat", type=int, default=20)
    ap.add_argument("--once", action="store_true", help="run the pipeline once and print nothing (a whole-process timing)")
    a = ap.parse_args()
    if a.once:
        pipeline()
        return
    sec, (th, std, rel, cross) = best_of(pipeline, a.repeat)
    files = (load("DATA_EMPS.mat"), load("DATA_EMPS_PULSES.mat"))
    compute_sec, _ = best_of(lambda: pipeline(files), a.repeat)
    params = dict(zip(NAMES, th.tolist()))
    emit({"task": "emps_idim", "seconds": sec, "compute_seconds": compute_sec, "parameters": params, "std": dict(zip(NAMES, std.tolist())),
          "relative_error_percent": rel, "cross_test_percent": cross,
          "accuracy": {"max_param_rel_err_vs_published": max(abs(params[n] - PUBLISHED[n]) / abs(PUBLISHED[n]) for n in NAMES)}})


if __name__ == "__main__":
    main()
