#!/usr/bin/env python3
"""Peer reference values for frictionlab's signal layer and IDIM on EMPS (scipy 1.10, numpy 1.24).

Usage: /usr/bin/python3 tests/peers/emps_idim_reference.py [--signal-csv OUTDIR]
Prints the filter coefficients and the EMPS IDIM-LS numbers (README recipe); with --signal-csv
writes the signal-layer reference series (filtfilt, decimate, gradient) as CSV files.
"""
import os
import sys

import numpy as np
import scipy.io
import scipy.signal as sg

HERE = os.path.dirname(os.path.abspath(__file__))
DATA = os.path.join(HERE, "..", "..", "data", "emps")


def test_signal(n=300):
    k = np.arange(n)
    return np.sin(0.05 * k) + 0.3 * np.cos(0.31 * k + 0.2) + 0.01 * k + 0.2 * np.sign(np.sin(0.013 * k * k / 10))


def write_signal_csv(outdir):
    x = test_signal()
    b, a = sg.butter(4, 0.2)
    cols = {
        "x": x,
        "filtfilt_butter4_0p2_pad12": sg.filtfilt(b, a, x, padtype="odd", padlen=12),
        "filtfilt_butter4_0p2_default": sg.filtfilt(b, a, x),
        "filtfilt_cheby1_5_1_0p3_default": sg.filtfilt(*sg.cheby1(5, 1.0, 0.3), x),
        "gradient_dt0p001": np.gradient(x, 0.001),
    }
    with open(os.path.join(outdir, "ref_filtfilt.csv"), "w") as f:
        f.write(",".join(cols) + "\n")
        for i in range(len(x)):
            f.write(",".join("%.17g" % cols[c][i] for c in cols) + "\n")
    d = {"decimate10": sg.decimate(x, 10), "decimate3": sg.decimate(x, 3)}
    for name, y in d.items():
        with open(os.path.join(outdir, "ref_%s.csv" % name), "w") as f:
            f.write("y\n")
            for v in y:
                f.write("%.17g\n" % v)


def pipeline(fname, asym=False):
    m = scipy.io.loadmat(os.path.join(DATA, fname))
    t, qm, vir, gtau = m["t"].ravel(), m["qm"].ravel(), m["vir"].ravel(), float(m["gtau"].ravel()[0])
    dt = (t[-1] - t[0]) / (len(t) - 1)  # mean step: t[1] - t[0] is 1.00002 ms in the file
    b, a = sg.butter(4, 100 / (0.5 / dt))
    qf = sg.filtfilt(b, a, qm, padtype="odd", padlen=12)
    qd = np.gradient(qf, dt)
    qdd = np.gradient(qd, dt)
    if asym:
        X = np.column_stack([qdd, qd * (qd > 0), (qd > 0) * 1.0, qd * (qd < 0), -1.0 * (qd < 0)])
    else:
        X = np.column_stack([qdd, qd, np.sign(qd), np.ones_like(qd)])
    y = gtau * vir
    X, y = X[49:], y[49:]
    Xd = np.column_stack([sg.decimate(X[:, j], 10) for j in range(X.shape[1])])
    yd = sg.decimate(y, 10)
    return Xd, yd


def main():
    np.set_printoptions(precision=17)
    for n, wn in [(4, 0.2), (2, 0.5), (5, 0.05), (8, 0.9)]:
        b, a = sg.butter(n, wn)
        print("butter", n, wn, "b", repr(b), "a", repr(a))
    for n, rp, wn in [(8, 0.05, 0.08), (5, 1.0, 0.3), (3, 0.5, 0.6)]:
        b, a = sg.cheby1(n, rp, wn)
        print("cheby1", n, rp, wn, "b", repr(b), "a", repr(a))
    print("cheby1 sos 8 0.05 0.08", repr(sg.cheby1(8, 0.05, 0.08, output="sos")))
    for asym in (False, True):
        X, y = pipeline("DATA_EMPS.mat", asym)
        th, *_ = np.linalg.lstsq(X, y, rcond=None)
        e = y - X @ th
        s2 = e @ e / (len(y) - X.shape[1])
        std = np.sqrt(s2 * np.diag(np.linalg.inv(X.T @ X)))
        print("asym" if asym else "sym", "N", len(y), "theta", repr(th), "std", repr(std))
        print("  relerr %.12g rmse %.12g cond %.12g" % (100 * np.linalg.norm(e) / np.linalg.norm(y),
                                                      np.sqrt(e @ e / len(y)), np.linalg.cond(X)))
        X2, y2 = pipeline("DATA_EMPS_PULSES.mat", asym)
        e2 = y2 - X2 @ th
        print("  cross %.12g" % (100 * np.linalg.norm(e2) / np.linalg.norm(y2)))
    if len(sys.argv) > 2 and sys.argv[1] == "--signal-csv":
        write_signal_csv(sys.argv[2])


if __name__ == "__main__":
    main()
