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


def test_contact_of_a_two_axis_table(example):
    # examples/map_xy_traverse.yaml: x traverses at 20 mm/s, y holds its place.
    vary = "plant.axes.x.mass=10:20:2"
    x = fl.analyze_map(example("map_xy_traverse"), vary)
    y = fl.analyze_map(example("map_xy_traverse"), vary, contact="y")
    assert [r["class"] for r in x] == ["steady-sliding"] * 2 and {r["contact"] for r in x} == {"x"}
    assert [r["class"] for r in y] == ["converged"] * 2 and {r["contact"] for r in y} == {"y"}
    by_index = fl.analyze_map(example("map_xy_traverse"), vary, contact=1)
    assert [(r["class"], r["contact"], r["amplitude"]) for r in by_index] == [(r["class"], r["contact"], r["amplitude"]) for r in y]
    with pytest.raises(ValueError, match=r"contact 'z': the xy-table plant has no such contact; its 2 contacts: 0 x, 1 y"):
        fl.analyze_map(example("map_xy_traverse"), vary, contact="z")
    with pytest.raises(ValueError, match="contact -1: expected an index from 0"):
        fl.analyze_map(example("map_xy_traverse"), vary, contact=-1)
    with pytest.raises(TypeError, match="argument contact"):
        fl.analyze_map(example("map_xy_traverse"), vary, contact=1.5)
    # A 1-DOF plant has one unnamed contact: its rows say ''.
    assert {r["contact"] for r in fl.analyze_map(example("map_pid_hunting"), "friction.Fs=1.5:1.5:1")} == {""}
