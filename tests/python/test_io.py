"""frictionlab.load (CSV, MAT), load_law, sha256_file: values and error messages."""
import json

import numpy as np
import pytest

import frictionlab as fl

EMPS_SHA256 = "6cf6814ae14618795da0101aae2bb97ff0c6351b0501b5492751b02b07facf7e"  # data/emps/README.md


def test_load_mat_columns_and_scalars(emps):
    assert emps.columns == ["qg", "qm", "t", "vir"]
    assert emps["t"].shape == (24841,) and emps["t"].dtype == np.float64
    assert emps["gtau"] == pytest.approx(35.15065188, rel=1e-9)
    assert emps.scalars["kp"] == pytest.approx(160.18)
    assert emps.sha256 == EMPS_SHA256
    assert fl.sha256_file(emps.file) == EMPS_SHA256


def test_load_csv(tmp_path):
    p = tmp_path / "run.csv"
    p.write_text("# a comment\ntime, velocity\n0,1.5\n0.5,-2e-3\n")
    d = fl.load(p)
    assert d.columns == ["time", "velocity"]
    np.testing.assert_array_equal(d["velocity"], [1.5, -2e-3])
    np.testing.assert_array_equal(d.lines, [3, 4])
    p2 = tmp_path / "semi.csv"
    p2.write_text("a;b\n1;2\n3;\n")
    assert fl.load(p2, delimiter=";", drop_invalid=True)["b"].tolist() == [2.0]


def test_load_errors_name_file_line_and_column(tmp_path):
    p = tmp_path / "bad.csv"
    p.write_text("time,force\n0,1\n0.1,abc\n")
    with pytest.raises(ValueError, match=r"bad.csv: line 3, column 2 'force': expected a number, got 'abc'"):
        fl.load(p)
    with pytest.raises(ValueError, match=r"nope.txt.*\.csv"):
        fl.load(tmp_path / "nope.txt")
    with pytest.raises(ValueError, match="missing.mat"):
        fl.load(tmp_path / "missing.mat")
    with pytest.raises(ValueError, match="delimiter"):
        fl.load(p, delimiter=";;")


def test_missing_column_lists_contents(emps):
    with pytest.raises(KeyError, match=r"no column 'x'; the file has columns: qg, qm, t, vir \(scalars: gtau, kp, kv\)"):
        emps["x"]


def test_load_law_yaml_json_and_model_json(tmp_path):
    (tmp_path / "law.yaml").write_text("law: coulomb-viscous\nFc: 2\nFv: 0.5\n")
    assert fl.load_law(tmp_path / "law.yaml").parameters == {"Fc": 2.0, "Fv": 0.5}
    (tmp_path / "law.json").write_text(json.dumps({"law": "coulomb", "Fc": 3}))
    assert fl.load_law(str(tmp_path / "law.json")).parameters == {"Fc": 3.0}
    (tmp_path / "bad.yaml").write_text("law: coulomb\nFc: -1\n")
    with pytest.raises(ValueError, match=r"bad.yaml.*coulomb: Fc = -1 must be >= 0"):
        fl.load_law(tmp_path / "bad.yaml")
