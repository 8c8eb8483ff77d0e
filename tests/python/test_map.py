"""fl.analyze_map: the same rows as `frictionlab analyze map`, the classes of the PID hunting map,
and its errors."""
import csv
import math
import subprocess

import pytest

import frictionlab as fl

VARY = "friction.Fs=1:2:3"  # Fs = Fc (converges), 1.5 and 2 (hunting)


def test_rows_match_the_cli(cli, example, tmp_path):
    rows = fl.analyze_map(example("map_pid_hunting"), VARY, jobs=2)
    assert [r["class"] for r in rows] == ["converged", "hunting", "hunting"]
    assert [r["index"] for r in rows] == [0, 1, 2]
    out = tmp_path / "map.csv"
    subprocess.run([cli, "analyze", "map", str(example("map_pid_hunting")), "--vary", VARY, "-o", str(out)],
                   check=True, capture_output=True)
    with open(out, newline="") as f:
        table = list(csv.DictReader(f))
    assert len(table) == len(rows)
    for mine, theirs in zip(rows, table):
        for key, text in theirs.items():
            value = mine[key]
            if isinstance(value, float):
                # The CSV holds the shortest form that reads back exactly: equal, not close.
                assert (math.isnan(value) and text == "") or float(text) == value, (key, value, text)
            else:
                assert value == text, (key, value, text)


def test_hunting_amplitude_grows_with_stiction(example):
    rows = fl.analyze_map(example("map_pid_hunting"), {"friction.Fs": (1.5, 2.5, 2)})
    assert all(r["class"] == "hunting" and r["theory"] == "hunting" for r in rows)
    assert rows[1]["amplitude"] > rows[0]["amplitude"] > 0
    assert rows[1]["theory_amplitude"] > rows[0]["theory_amplitude"] > 0


def test_shard_and_errors(example):
    part = fl.analyze_map(example("map_pid_hunting"), VARY, shard="2/2")
    assert [r["index"] for r in part] == [1]
    with pytest.raises(ValueError, match="friction.Fx"):
        fl.analyze_map(example("map_pid_hunting"), "friction.Fx=1:2:2")
    with pytest.raises(ValueError, match="vary 'friction.Fs=1:2'"):
        fl.analyze_map(example("map_pid_hunting"), "friction.Fs=1:2")
    with pytest.raises(TypeError, match="argument vary"):
        fl.analyze_map(example("map_pid_hunting"), 3)
    with pytest.raises(ValueError, match="shard '3/2'"):
        fl.analyze_map(example("map_pid_hunting"), VARY, shard="3/2")
