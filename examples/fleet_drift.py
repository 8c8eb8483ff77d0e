"""A fleet's drift: eight daily constant-velocity logs of one axis (and three broken files),
one sweep identification per file on a two-worker Dask LocalCluster, the drift table and its
figure. The axis' Coulomb friction rises by 30 % on the sixth day, and the drift rule at 3
combined standard deviations flags that change and no other. As

    python3 examples/fleet_logs.py logs
    frictionlab identify sweep logs --resample --model coulomb-viscous --jobs 2 --table fleet.csv \\
        --date-from name --drift drift.csv --drift-threshold 3 --plot drift.svg

Usage: python3 examples/fleet_drift.py [OUTPUT_DIR]
"""
import pathlib
import sys
import tempfile

import frictionlab as fl

sys.path.insert(0, str(pathlib.Path(__file__).resolve().parent))
import fleet_logs  # noqa: E402

if __name__ == "__main__":  # the Dask workers import this file's module: run only as a script
    out = pathlib.Path(sys.argv[1]) if len(sys.argv) > 1 else None
    with tempfile.TemporaryDirectory() as logs:
        fleet_logs.write_fleet(logs)
        t = fl.batch.identify(logs, "sweep", model="coulomb-viscous", load={"resample": True}, date_from="name",
                              workers=2)
    print(t)
    for r in t:
        if r["status"] == "ok":
            print(f"{r['date']}  Fc = {r['Fc']:.4f} +- {r['Fc_std']:.4f} {r['Fc_unit']}  "
                  f"Fv = {r['Fv']:.5f} +- {r['Fv_std']:.5f} {r['Fv_unit']}")
        else:
            print(f"{r['file'].rsplit('/', 1)[-1]}: {r['message']}")
    d = fl.batch.drift(t, threshold=3.0)
    flagged = [(r["parameter"], r["date"]) for r in d if r["flagged"]]
    print("flagged:", flagged)
    assert flagged == [("Fc", f"2026-11-{fleet_logs.WORN_FROM_DAY:02d}")], flagged
    if out:
        out.mkdir(parents=True, exist_ok=True)
        t.to_csv(out / "fleet.csv", overwrite=True)
        d.to_csv(out / "drift.csv", overwrite=True)
        fl.plot.drift(d, file=out / "drift.png")
