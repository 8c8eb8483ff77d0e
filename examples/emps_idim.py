"""EMPS benchmark, IDIM-LS from Python: the same identification as

    frictionlab identify idim data/emps/DATA_EMPS.mat --time t --position qm --input vir --gain gtau \
        --validate data/emps/DATA_EMPS_PULSES.mat

then the best model of the CLI help (asymmetric friction, a Stribeck term, one-sample delay).
Usage: python3 examples/emps_idim.py [OUTPUT_DIR]   (figures go to OUTPUT_DIR when given)
"""
import pathlib
import sys

import frictionlab as fl

data = pathlib.Path(__file__).resolve().parents[1] / "data" / "emps"
out = pathlib.Path(sys.argv[1]) if len(sys.argv) > 1 else None

ident = fl.load(data / "DATA_EMPS.mat")
check = fl.load(data / "DATA_EMPS_PULSES.mat")
force = ident["gtau"] * ident["vir"]  # N: drive gain (N/V) times the controller output (V)

r = fl.identify_idim(ident["t"], force, position=ident["qm"], source=ident,
                     validate={"time": check["t"], "force": check["gtau"] * check["vir"], "position": check["qm"],
                               "source": check})
print(r)
assert abs(r["M"] / 95.1089 - 1) < 5e-3, r["M"]  # published IDIM-LS inertia, kg

best = fl.identify_idim(ident["t"], force, ident["qm"], terms="inertia,asymmetric,stribeck", delay=1)
v = fl.cross_test(best, check["t"], check["gtau"] * check["vir"], check["qm"])
print(best)
print(f"cross-test on DATA_EMPS_PULSES.mat: {v.relative_error_percent:.3f} % (published model: 5.98 %)")

if out:
    out.mkdir(parents=True, exist_ok=True)
    fl.plot.idim(r, file=out / "emps_idim.png")
    r.save(out / "emps_model.json", overwrite=True)
