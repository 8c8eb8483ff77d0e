"""frictionlab.batch: one identification per file of a fleet's folder (realistic logs and broken
files), serially and on Dask (a two-worker LocalCluster gives the serial rows exactly), the
table's files, Monte Carlo simulations, the drift table and figure, and the package without dask."""
import csv
import json
import math
import os
import re
import subprocess
import sys
import time

import numpy as np
import pytest

import frictionlab as fl

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..", "examples"))
import fleet_logs  # noqa: E402

# The sweep's Fc on these logs is within 3 % of the truth: the ten levels' means average the
# noise (5 mN m) to about 0.3 mN m, and the sensor offset cancels between the two directions.
FC_REL_TOL = 0.03
# Fv likewise within 5 % (it rests on the spread of speeds, 0.2 to 4 rad/s).
FV_REL_TOL = 0.05
SWEEP = dict(model="coulomb-viscous", axis="rotary", load={"resample": True}, date_from="name")  # motors: N m


@pytest.fixture(scope="module")
def fleet(tmp_path_factory):
    folder = tmp_path_factory.mktemp("fleet")
    return str(folder), fleet_logs.write_fleet(str(folder))


@pytest.fixture(scope="module")
def serial(fleet):
    folder, _ = fleet
    return fl.batch.identify(folder, "sweep", client=None, **SWEEP)


def test_one_row_per_file_failures_in_their_rows(fleet, serial):
    folder, truth = fleet
    t = serial
    assert [os.path.basename(f) for f in t["file"]] == sorted(truth)
    assert list(t["index"]) == list(range(len(truth)))
    by_name = {os.path.basename(r["file"]): r for r in t}
    for name, Fc in truth.items():
        r = by_name[name]
        if Fc is None:
            assert r["status"] == "error" and r["method"] == "sweep", name
            assert name in r["message"], r["message"]
            continue
        assert r["status"] == "ok", (name, r["message"])
        assert r["date"] == name[6:16]
        assert r["Fc"] == pytest.approx(Fc, rel=FC_REL_TOL)
        assert r["Fv"] == pytest.approx(fleet_logs.FV, rel=FV_REL_TOL)
        assert 0 < r["Fc_std"] < 0.1 * Fc
        assert r["Fc_unit"] == "N m" and r["Fv_unit"] == "N m s/rad"
        assert r["axis"] == "rotary" and r["model"] == "coulomb-viscous"
        assert r["samples"] == 10 and r["relative_error_percent"] < 5
        assert len(r["sha256"]) == 64
    # Each broken file says what is wrong with it.
    assert "force" in by_name["axis3_2026-11-20_no_force.csv"]["message"]
    assert "n/a" in by_name["axis3_2026-11-21_text.csv"]["message"] or "line" in by_name["axis3_2026-11-21_text.csv"]["message"]
    assert "empty" in by_name["axis3_2026-11-22_empty.csv"]["message"]
    assert len(t.ok) == fleet_logs.DAYS and len(t.failed) == len(fleet_logs.BROKEN)
    assert t.columns[:8] == ["index", "file", "date", "status", "message", "method", "model", "axis"]
    assert t.columns[-5:] == list(fl.batch.FIT_COLUMNS)


def test_two_worker_local_cluster_gives_the_serial_rows(fleet, serial):
    folder, _ = fleet
    # The default: a LocalCluster of two worker processes, started and closed by the call.
    on_cluster = fl.batch.identify(folder, "sweep", workers=2, **SWEEP)
    assert on_cluster.json_text() == serial.json_text()
    assert on_cluster.csv_text() == serial.csv_text()


def test_a_client_passed_in_is_used(fleet, serial):
    from distributed import Client, LocalCluster

    folder, _ = fleet
    with LocalCluster(n_workers=2, threads_per_worker=1, processes=False, dashboard_address=None) as cluster, \
            Client(cluster) as client:
        t = fl.batch.identify(folder + "/axis3_2026-11-0*.csv", "sweep", client=client, **SWEEP)
        assert len(client.scheduler_info()["workers"]) == 2
    assert t.json_text() == fl.batch.Table(serial.ok, serial.columns).json_text()


def _dies_on_day_2(d):
    """Arrays of a sweep log; the worker process dies (as a crash in native code would) on day 2,
    half a second in: the worker has then told the scheduler of the task it finished before (a
    death at once can come before that message, and Dask would count the death to that task too)."""
    if d.file.endswith("2026-11-02.csv"):
        time.sleep(0.5)
        os._exit(3)
    return {"time": d["time"], "force": d["force"], "velocity": d["velocity"]}


def test_a_worker_lost_is_its_row_or_its_chunks_rows(fleet, serial):
    import dask
    from distributed import Client, LocalCluster

    folder, _ = fleet
    # Day 2 (its worker dies) last: nothing waits behind it on the worker that dies (a task
    # queued there would count the death too).
    days = (3, 1, 4, 2)
    files = [folder + f"/axis3_2026-11-0{k}.csv" for k in days]
    # One retry instead of Dask's three: the chunk is lost after two worker deaths (quicker).
    with dask.config.set({"distributed.scheduler.allowed-failures": 1}), \
            LocalCluster(n_workers=2, threads_per_worker=1, processes=True, dashboard_address=None,
                         silence_logs=50) as cluster, Client(cluster) as client:
        # Automatic chunks: 4 files on 2 threads are 4 chunks of 1; only day 2's row is lost.
        alone = fl.batch.identify(files, "sweep", columns=_dies_on_day_2, client=client, model="coulomb-viscous",
                                  load={"resample": True})
        # Chunks of 2: days 4 and 2 run in one task; both rows are lost, days 3 and 1 are not.
        paired = fl.batch.identify(files, "sweep", columns=_dies_on_day_2, client=client, chunk=2,
                                   model="coulomb-viscous", load={"resample": True})
    for t, lost in ((alone, [3]), (paired, [2, 3])):
        assert [r["file"] for r in t] == files and list(t["index"]) == [0, 1, 2, 3]
        for i, day in enumerate(days):
            r = t[i]
            if i not in lost:
                assert r["status"] == "ok" and r["Fc"] == serial[day - 1]["Fc"], r
                continue
            assert r["status"] == "error" and r["method"] is None, r
            what = "1 job" if len(lost) == 1 else "2 jobs, index 2 to 3"
            assert r["message"].startswith(f"worker lost while running this job's chunk ({what}): KilledWorker"), \
                r["message"]


class _RecordingClient:
    """A dask Client that records the chunk sizes of each map (how the jobs were sent)."""

    def __init__(self, client):
        self.client = client
        self.sizes = []

    def nthreads(self):
        return self.client.nthreads()

    def map(self, function, chunks, **kwargs):
        self.sizes.append([len(c) for c in chunks])
        return self.client.map(function, chunks, **kwargs)


@pytest.fixture(scope="module")
def two_workers():
    from distributed import Client, LocalCluster

    with LocalCluster(n_workers=2, threads_per_worker=1, processes=True, dashboard_address=None,
                      silence_logs=50) as cluster, Client(cluster) as client:
        yield client


def test_chunks_give_the_serial_rows_in_order(fleet, two_workers):
    folder, truth = fleet
    ok = [os.path.join(folder, n) for n in sorted(truth) if truth[n] is not None]
    broken = [os.path.join(folder, n) for n in sorted(truth) if truth[n] is None]
    # 11 files, a broken one in the middle of chunks of 3 (the first two) and at a chunk's end.
    files = ok[:1] + broken[:1] + ok[1:3] + broken[1:2] + ok[3:6] + broken[2:] + ok[6:]
    assert len(files) == 11
    serial = fl.batch.identify(files, "sweep", client=None, **SWEEP)
    assert [r["status"] for r in serial].count("error") == 3
    for chunk, sizes in ((1, [1] * 11), (3, [3, 3, 3, 2]), (None, [2, 2, 2, 2, 2, 1]), (np.int64(20), [11])):
        client = _RecordingClient(two_workers)
        t = fl.batch.identify(files, "sweep", client=client, chunk=chunk, **SWEEP)
        # None on 2 worker threads: about 4 chunks per thread, ceil(11 / 8) = 2 files each.
        assert client.sizes == [sizes], (chunk, client.sizes)
        assert t.json_text() == serial.json_text(), chunk
        assert t.csv_text() == serial.csv_text(), chunk
    # The failing files kept their own rows and messages; their chunk neighbours are ok.
    assert t[1]["status"] == "error" and "force" in t[1]["message"]
    assert t[0]["status"] == "ok" and t[2]["status"] == "ok"


def _fails_on_odd_index(job):
    """A row function that raises (as an internal error would) for odd indices."""
    if job["head"]["index"] % 2:
        raise RuntimeError("boom")
    return {**job["head"], "status": "ok", "message": ""}


def test_a_chunk_that_raises_gives_each_of_its_jobs_an_error_row(two_workers):
    jobs = [{"head": {"index": i, "file": f"f{i}.csv"}} for i in range(5)]
    rows = fl.batch._run_on(two_workers, _fails_on_odd_index, jobs, 2)
    assert [r["file"] for r in rows] == [f"f{i}.csv" for i in range(5)]
    for r in rows[:4]:
        lo = 2 * (r["index"] // 2)
        assert r["status"] == "error", r
        assert r["message"] == f"worker failed on this job's chunk (2 jobs, index {lo} to {lo + 1}): RuntimeError: boom"
    assert rows[4] == {"index": 4, "file": "f4.csv", "status": "ok", "message": ""}


def test_chunk_size_rule():
    assert fl.batch.CHUNKS_PER_THREAD == 4
    assert fl.batch._chunk_size(None, 400, 2) == 50
    assert fl.batch._chunk_size(None, 401, 2) == 51
    assert fl.batch._chunk_size(None, 3, 2) == 1  # at least one job per chunk
    assert fl.batch._chunk_size(None, 10, 0) == 3  # no worker yet: counted as one thread
    assert fl.batch._chunk_size(7, 3, 2) == 7


@pytest.mark.parametrize("bad", [0, -3, 2.5, True, "4", [2]])
def test_bad_chunk_values_are_refused_before_any_work(fleet, bad):
    folder, _ = fleet
    message = re.escape(f"chunk = {bad!r}: expected None") + ".* or a whole number >= 1 of jobs per chunk"
    with pytest.raises(ValueError, match=message):
        fl.batch.identify(folder, "sweep", client=None, chunk=bad)
    # Before the cluster is started or the data looked at.
    with pytest.raises(ValueError, match=message):
        fl.batch.identify("no/such/folder/*.csv", "sweep", client="local", chunk=bad)
    with pytest.raises(ValueError, match=message):
        fl.batch.simulate(make=_monte_carlo_scenario, seeds=range(3), client=None, chunk=bad)


def test_simulate_chunks_give_the_serial_rows(example, two_workers):
    scenarios = [{"plant": {"type": "axis", "M": 1.0}, "friction": {"law": "coulomb", "Fc": 0.5 + 0.1 * k},
                  "input": {"type": "ramp", "rate": 1.0}, "duration": 2.0, "output_rate": 50} for k in range(7)]
    scenarios[4] = {"plant": {"type": "nope"}}  # fails in the middle of the second chunk of 3
    serial = fl.batch.simulate(scenarios, client=None)
    mc_serial = fl.batch.simulate(make=_monte_carlo_scenario, seeds=range(7), client=None)
    for chunk, sizes in ((3, [3, 3, 1]), (None, [1] * 7)):
        client = _RecordingClient(two_workers)
        t = fl.batch.simulate(scenarios, client=client, chunk=chunk)
        assert t.json_text() == serial.json_text(), chunk
        mc = fl.batch.simulate(make=_monte_carlo_scenario, seeds=range(7), client=client, chunk=chunk)
        assert mc.json_text() == mc_serial.json_text(), chunk
        assert client.sizes == [sizes, sizes], (chunk, client.sizes)
    assert [r["status"] for r in t] == ["ok"] * 4 + ["error"] + ["ok"] * 2
    assert t[4]["scenario"] == "#4" and "nope" in t[4]["message"]
    # A Coulomb level Fc under a 1 N/s ramp breaks away at t = Fc (< 2 s): once per run.
    assert [r["breakaways"] for r in t if r["status"] == "ok"] == [1] * 6


def test_table_files_and_structured_array(serial, tmp_path):
    t = serial
    out_csv, out_json = tmp_path / "t.csv", tmp_path / "t.json"
    t.to_csv(out_csv)
    t.to_json(out_json)
    with pytest.raises(ValueError, match="exists"):
        t.to_csv(out_csv)
    t.to_csv(out_csv, overwrite=True)
    rows = list(csv.DictReader(open(out_csv)))
    assert len(rows) == len(t)
    for r, row in zip(rows, t):
        assert r["status"] == row["status"]
        if row["status"] == "ok":
            assert float(r["Fc"]) == row["Fc"]  # 17 digits: read back exactly
        else:
            assert r["Fc"] == ""
    j = json.load(open(out_json))
    assert j["schema"] == 1 and j["kind"] == "identify" and j["columns"] == t.columns
    assert j["rows"][-1]["Fc"] is None and j["rows"][0]["Fc"] == t[0]["Fc"]
    a = t.to_array()
    assert a.dtype["index"] == np.int64 and a.dtype["Fc"] == np.float64 and a.dtype["file"].kind == "U"
    assert np.isnan(a["Fc"][-1]) and a["Fc"][0] == t[0]["Fc"]
    with pytest.raises(KeyError, match="no column 'Fx'"):
        t["Fx"]
    assert not list(tmp_path.glob("*.tmp*"))


def test_data_files_forms_and_errors(fleet, tmp_path):
    folder, truth = fleet
    assert len(fl.batch.data_files(folder)) == len(truth)
    assert len(fl.batch.data_files(folder + "/axis3_2026-11-0?.csv")) == fleet_logs.DAYS
    listed = fl.batch.data_files([folder + "/axis3_2026-11-02.csv", folder + "/axis3_2026-11-01.csv"])
    assert [os.path.basename(f) for f in listed] == ["axis3_2026-11-02.csv", "axis3_2026-11-01.csv"]
    with pytest.raises(ValueError, match="has no .csv or .mat file"):
        fl.batch.data_files(str(tmp_path))
    with pytest.raises(ValueError, match="matches no file"):
        fl.batch.data_files(folder + "/*.txt")
    with pytest.raises(ValueError, match="method 'swep'"):
        fl.batch.identify(folder, "swep", client=None)
    with pytest.raises(ValueError, match="client = 'remote': expected 'local', None"):
        fl.batch.identify(folder, "sweep", client="remote")
    with pytest.raises(ValueError, match="workers = 0: expected a whole number >= 1"):
        fl.batch.identify(folder, "sweep", workers=0)
    with pytest.raises(TypeError, match="load: expected a dict"):
        fl.batch.identify(folder, "sweep", client=None, load=True)
    with pytest.raises(ValueError, match="date_from = 'day'"):
        fl.batch.identify(folder, "sweep", client=None, date_from="day")
    with pytest.raises(TypeError, match="batch data: 3 is a int"):
        fl.batch.identify([folder, 3], "sweep", client=None)
    # A file that is not there is its own error row.
    t = fl.batch.identify([folder + "/missing_2026-11-30.csv"], "sweep", client=None)
    assert t[0]["status"] == "error" and "missing_2026-11-30.csv" in t[0]["message"]


def test_columns_mapping_and_function(fleet):
    folder, _ = fleet
    f = folder + "/axis3_2026-11-01.csv"
    by_default = fl.batch.identify(f, "sweep", client=None, model="coulomb-viscous", load={"resample": True})
    named = fl.batch.identify(f, "sweep", client=None, model="coulomb-viscous", load={"resample": True},
                              columns={"force": "force", "velocity": "velocity"})
    derived = fl.batch.identify(f, "sweep", client=None, model="coulomb-viscous", load={"resample": True},
                                columns=lambda d: {"time": d["time"], "force": 2.0 * d["force"], "velocity": d["velocity"]})
    assert named[0]["Fc"] == by_default[0]["Fc"]
    # Twice the torque: twice Fc (the fit is linear in the force).
    assert derived[0]["Fc"] == pytest.approx(2.0 * by_default[0]["Fc"], rel=1e-9)
    bad = fl.batch.identify(f, "sweep", client=None, load={"resample": True}, columns={"torque": "force"})
    assert bad[0]["status"] == "error" and "'torque' is not an array of this method" in bad[0]["message"]


def test_drift_flags_the_wear_step(serial):
    d = fl.batch.drift(serial, threshold=3.0)
    assert d.kind == "drift" and d.columns == list(fl.batch.DRIFT_COLUMNS)
    fc = [r for r in d if r["parameter"] == "Fc"]
    assert [r["date"] for r in fc] == [f"2026-11-{k:02d}" for k in range(1, fleet_logs.DAYS + 1)]
    flagged = [r["date"] for r in fc if r["flagged"]]
    assert flagged == [f"2026-11-{fleet_logs.WORN_FROM_DAY:02d}"]
    step = fc[fleet_logs.WORN_FROM_DAY - 1]
    assert step["change"] == pytest.approx(fleet_logs.FC_WORN - fleet_logs.FC, rel=0.2)
    assert step["combined_std"] == pytest.approx(math.hypot(step["std"], fc[fleet_logs.WORN_FROM_DAY - 2]["std"]))
    assert math.isnan(fc[0]["change"]) and not fc[0]["flagged"]
    # The drift table has no status column: its repr counts the flagged rows, not failures.
    n_flagged = sum(1 for r in d if r["flagged"])
    assert n_flagged >= 1 and d.failed == []
    assert repr(d).startswith(f"Table(drift: {len(d)} rows, {n_flagged} flagged; columns"), repr(d)
    assert "failed" not in repr(d)
    assert re.match(r"Table\(identify: \d+ rows, \d+ ok, \d+ failed; columns", repr(serial)), repr(serial)
    # Only Fc: the table's other parameters when none is named.
    assert {r["parameter"] for r in fl.batch.drift(serial, ["Fc"])} == {"Fc"}
    assert {r["parameter"] for r in d} == {"Fc", "Fv"}
    with pytest.raises(ValueError, match="no date"):
        fl.batch.drift([{"file": "x.csv", "status": "ok", "Fc": 1.0, "Fc_std": 0.1, "Fc_unit": "N"}])
    with pytest.raises(ValueError, match="threshold"):
        fl.batch.drift(serial, threshold=0)


def test_drift_figure(serial, tmp_path):
    pytest.importorskip("matplotlib")
    fig = fl.plot.drift(fl.batch.drift(serial, threshold=3.0), file=tmp_path / "drift.png")
    assert len(fig.axes) == 2
    assert (tmp_path / "drift.png").stat().st_size > 1000
    # The Fc panel circles the one flagged log.
    assert any(line.get_label().startswith("change >") for line in fig.axes[0].get_lines())


def test_log_date_forms():
    assert fl.batch.log_date("a/axis3_2026-11-02.csv") == ("2026-11-02", 1793577600.0)
    assert fl.batch.log_date("log-20261102T0815.mat")[0] == "2026-11-02T08:15:00"
    assert fl.batch.log_date("axis3.csv") is None
    d = fl.Data([("time", np.array([1793577600.0 + 3600]))], {})
    assert fl.batch.log_date("x.csv", "column:time", d)[0] == "2026-11-02T01:00:00"
    with pytest.raises(ValueError, match="date_from"):
        fl.batch.log_date("x.csv", "file")


def _monte_carlo_scenario(seed):
    rng = np.random.default_rng(seed)
    return {"plant": {"type": "axis", "M": 1.0},
            "friction": {"law": "coulomb", "Fc": 1.0 + 0.1 * rng.standard_normal()},
            "input": {"type": "ramp", "rate": 1.0}, "duration": 3.0, "output_rate": 100}


def test_simulate_monte_carlo_serial_equals_cluster(example):
    serial = fl.batch.simulate(make=_monte_carlo_scenario, seeds=range(6), client=None)
    threads = fl.batch.simulate(make=_monte_carlo_scenario, seeds=range(6), workers=2, processes=False)
    assert serial.json_text() == threads.json_text()
    assert all(r["status"] == "ok" for r in serial), [r["message"] for r in serial]
    # A ramp of 1 N/s breaks a Coulomb level Fc away at t = Fc: one breakaway per run.
    assert list(serial["breakaways"]) == [1] * 6
    assert len(set(serial["final_velocity"])) == 6  # each seed its own Fc
    listed = fl.batch.simulate([example("craig_motor_trapezoid"), {"plant": {"type": "nope"}}], client=None,
                               duration=1.0)
    assert listed[0]["status"] == "ok" and listed[0]["scenario"].endswith("craig_motor_trapezoid.yaml")
    assert listed[1]["status"] == "error" and listed[1]["scenario"] == "#1" and "nope" in listed[1]["message"]
    with pytest.raises(ValueError, match="make needs seeds"):
        fl.batch.simulate(make=_monte_carlo_scenario)


def test_package_and_serial_batch_without_dask(fleet):
    folder, _ = fleet
    code = (
        "import sys\n"
        "sys.modules['dask'] = None\n"
        "sys.modules['distributed'] = None\n"
        "import frictionlab as fl\n"
        f"t = fl.batch.identify({folder!r} + '/axis3_2026-11-01.csv', 'sweep', client=None, "
        "model='coulomb-viscous', load={'resample': True})\n"
        "assert t[0]['status'] == 'ok', t[0]['message']\n"
        "try:\n"
        f"    fl.batch.identify({folder!r}, 'sweep')\n"
        "except ImportError as e:\n"
        "    print('no dask:', e)\n"
    )
    out = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True, env=os.environ)
    assert out.returncode == 0, out.stderr
    assert "no dask:" in out.stdout


def _docs_dask_snippet():
    """The first ```python block of docs/fleet.md that runs fl.batch.identify on a LocalCluster."""
    from conftest import SOURCE_DIR

    text = (SOURCE_DIR / "docs" / "fleet.md").read_text(encoding="utf-8")
    blocks = re.findall(r"^```python\n(.*?)^```", text, re.M | re.S)
    snippet = next(b for b in blocks if "fl.batch.identify(" in b and "client=" not in b)
    # Up to the first table written: the EMPS-style and Monte Carlo lines need their own inputs.
    keep = snippet.split("# EMPS-style files")[0]
    assert "fl.batch.identify(" in keep, keep
    return keep


def test_docs_dask_snippet_as_a_plain_script_fails_at_once_with_the_guard(fleet, tmp_path):
    # Pasted into a script without the main guard, the LocalCluster's spawned workers would import
    # the script again and start the batch again, for ever. The call refuses before any worker
    # starts, showing the guard. 60 s: a hang is what the test catches; the refusal takes ~1 s.
    script = tmp_path / "batch_script.py"
    script.write_text(_docs_dask_snippet(), encoding="utf-8")
    (tmp_path / "logs").mkdir()
    os.symlink(fleet[0], tmp_path / "logs" / "axis3")
    start = time.monotonic()
    p = subprocess.run([sys.executable, str(script)], cwd=tmp_path, capture_output=True, text=True, timeout=60)
    assert time.monotonic() - start < 60
    assert p.returncode != 0, p.stdout
    assert 'if __name__ == "__main__":' in p.stderr, p.stderr
    assert "batch_script.py, line" in p.stderr and "processes=False" in p.stderr, p.stderr


def test_guard_check_reads_where_the_script_calls_from(tmp_path):
    # Outside the guard: refused with the line; inside the guard (directly or through a function
    # called from it): accepted. No cluster is started: the check alone is called.
    script = tmp_path / "where.py"
    script.write_text(
        "import frictionlab as fl\n"
        "print('top', fl.batch._guarded_main_call())\n"
        "def f():\n"
        "    return fl.batch._guarded_main_call()\n"
        "if __name__ == '__main__':\n"
        "    print('guard', fl.batch._guarded_main_call())\n"
        "    print('function', f())\n", encoding="utf-8")
    out = subprocess.run([sys.executable, str(script)], capture_output=True, text=True, check=True).stdout
    assert f"top {script}, line 2" in out, out
    assert "guard None" in out and "function None" in out, out
    # python -c has no script file: never refused.
    out = subprocess.run([sys.executable, "-c", "import frictionlab as fl; print(fl.batch._guarded_main_call())"],
                         capture_output=True, text=True, check=True).stdout
    assert out.strip() == "None", out
