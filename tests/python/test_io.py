"""frictionlab.load (CSV, MAT), load_law, sha256_file: values and error messages."""
import json
import os

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


def test_load_format_reads_a_table_of_any_name(tmp_path):
    # A robot's .log is a text table by its content, not its name: format="csv" (the command
    # line's --format csv) reads it as the same table; .tsv and .txt are tables by extension.
    text = "time\tvelocity\n0\t1.5\n0.5\t-2e-3\n"
    for name in ("robot.log", "robot.tsv", "robot.txt"):
        (tmp_path / name).write_text(text)
    want = fl.load(tmp_path / "robot.tsv")
    for d in (fl.load(tmp_path / "robot.log", format="csv"), fl.load(tmp_path / "robot.txt")):
        assert d.columns == want.columns == ["time", "velocity"]
        np.testing.assert_array_equal(d["velocity"], want["velocity"])
    with pytest.raises(fl.Error, match="robot.log: unknown data file type '.log'") as e:
        fl.load(tmp_path / "robot.log")
    assert e.value.code == "data.file_type"
    with pytest.raises(fl.Error, match="format 'xls': expected csv") as e:
        fl.load(tmp_path / "robot.log", format="xls")
    assert e.value.code == "option.invalid" and e.value.option == "format"
    with pytest.raises(ValueError, match="robot.tsv"):
        fl.load(tmp_path / "robot.tsv", format="mat")
    with pytest.raises(TypeError, match="format"):
        fl.load(tmp_path / "robot.log", format=1)


def test_load_errors_name_file_line_and_column(tmp_path):
    p = tmp_path / "bad.csv"
    p.write_text("time,force\n0,1\n0.1,abc\n")
    with pytest.raises(ValueError, match=r"bad.csv: line 3, column 2 'force': expected a number, got 'abc'"):
        fl.load(p)
    with pytest.raises(ValueError, match=r"nope.log.*\.csv.*format=\"csv\""):
        fl.load(tmp_path / "nope.log")
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


def test_devices_are_refused_and_fifos_read_as_streams(tmp_path):
    """Input files are read once within the budget (docs/guarantees.md): sha256_file('/dev/zero')
    is refused at once (it used to hash without end), and so is a law .json linked to it; a FIFO is
    hashed or read as a law file as it streams."""
    import hashlib
    import subprocess
    import sys
    with pytest.raises(fl.Error, match="character device") as info:
        fl.sha256_file("/dev/zero")
    assert info.value.code == "data.file_unreadable"
    os.symlink("/dev/zero", tmp_path / "zero.json")  # a law file read as JSON (it was read without a check)
    with pytest.raises(fl.Error, match="character device"):
        fl.load_law(str(tmp_path / "zero.json"))
    for name, text in (("law.yaml", b"law: coulomb-viscous\nFc: 2\nFv: 0.5\n"),
                       ("law.json", b'{"law": "coulomb-viscous", "Fc": 2, "Fv": 0.5}\n')):
        fifo = tmp_path / name
        os.mkfifo(fifo)
        for read in (fl.sha256_file, fl.load_law):
            # The writer is another process, as a pipe's writer is.
            writer = subprocess.Popen([sys.executable, "-c", "import sys; open(sys.argv[1], 'wb').write(sys.argv[2].encode())",
                                       str(fifo), text.decode()])
            got = read(str(fifo))
            assert writer.wait(timeout=60) == 0
            if read is fl.sha256_file:
                assert got == hashlib.sha256(text).hexdigest()
            else:
                assert got.parameters == {"Fc": 2.0, "Fv": 0.5}, name


# ---- real rigs' logs: no header row, other delimiters, irregular time ------------------------

def _robot_log(path, rows=800, seed=5, hole_after=None):
    """A headerless joint log: 100 Hz nominal, stamps 10 to 12 ms apart, 31 columns; column 2 is
    a 0.5 Hz sine of 1 rad (joint 1)."""
    rng = np.random.default_rng(seed)
    steps = rng.uniform(0.010, 0.012, rows - 1)
    if hole_after is not None:
        steps[hole_after - 1] += 0.5
    t = 2.0 + np.concatenate([[0.0], np.cumsum(steps)])
    cols = [t, np.sin(np.pi * t)] + [np.full(rows, 0.1 * j) for j in range(29)]
    np.savetxt(path, np.column_stack(cols), delimiter=";", fmt="%.9g")
    return t


def test_load_headerless_log_names_and_resample(tmp_path):
    p = tmp_path / "joints.csv"
    t = _robot_log(p)
    d = fl.load(p)
    assert not d.header_row
    assert d.columns[:3] == ["c1", "c2", "c3"] and d.columns[-1] == "c31"
    assert d.resampling is None
    with pytest.raises(KeyError, match=r"no column 'time'.*c31.*no header row"):
        d["time"]

    d = fl.load(p, names="t,q1", resample=True)
    assert d.columns[:3] == ["t", "q1", "c3"]
    r = d.resampling
    assert 0.010 - 1e-9 <= r["dt_min"] <= r["dt_median"] <= r["dt_max"] <= 0.012 + 1e-9
    assert r["dt"] == r["dt_median"] and r["samples_in"] == 800
    assert r["samples_out"] == len(d["t"]) == int(np.floor((t[-1] - t[0]) / r["dt"] + 1e-9)) + 1
    steps = np.diff(d["t"])
    kStepRel = 1e-9  # the grid is t0 + i dt
    assert np.all(np.abs(steps - r["dt"]) <= kStepRel * r["dt"])
    # Linear interpolation of the sine: error <= h^2 w^2 / 8 with h <= 12 ms.
    kInterpTol = 0.012 ** 2 * np.pi ** 2 / 8
    assert np.max(np.abs(d["q1"] - np.sin(np.pi * d["t"]))) <= kInterpTol
    assert len(d.lines) == 0

    # A given step, names as a list; the time column chosen by name.
    d2 = fl.load(p, names=["time", "q1"], resample=0.02, time="time")
    assert d2.resampling["dt"] == 0.02


def test_load_delimiters_bom_crlf_quotes_and_extremes(tmp_path):
    p = tmp_path / "excel.csv"
    p.write_bytes(b'\xef\xbb\xbf"time"\t"force, N"\r\n0\t1e-400\r\n0.5\t2\r\n')
    d = fl.load(p)
    assert d.columns == ["time", "force, N"]
    assert d["force, N"].tolist() == [0.0, 2.0]
    (tmp_path / "spaces.csv").write_text("0.0  1.5\n0.1  2.5\n")
    assert fl.load(tmp_path / "spaces.csv")["c2"].tolist() == [1.5, 2.5]
    (tmp_path / "huge.csv").write_text("t,x\n0,1e400\n")
    with pytest.raises(ValueError, match=r"line 2, column 2 'x': '1e400' is out of the range of a double"):
        fl.load(tmp_path / "huge.csv")


def test_load_repeated_stamps_gap_and_max_gap(tmp_path):
    p = tmp_path / "holes.csv"
    p.write_text("time,f\n0,0\n0.01,1\n0.02,2\n0.02,4\n0.03,3\n0.04,4\n0.05,5\n0.06,6\n0.26,26\n0.27,27\n")
    with pytest.raises(ValueError, match=r"holes.csv: line 9 to line 10: a gap of 0.2 s.*max_gap 0.202"):
        fl.load(p, resample=True)
    d = fl.load(p, resample=True, max_gap=0.25)
    assert d.resampling["merged"] == 1 and d.resampling["max_gap"] == 0.25
    assert len(d.warnings) == 1 and "line 5" in d.warnings[0]
    kTol = 1e-9  # straight lines through integers
    assert d["f"][2] == pytest.approx(3.0, abs=kTol)    # mean of the repeated stamp's rows
    assert d["f"][16] == pytest.approx(16.0, abs=kTol)  # across the allowed hole


def test_load_argument_errors_name_the_argument(tmp_path, source_dir):
    p = tmp_path / "log.csv"
    _robot_log(p, rows=50)
    with pytest.raises(ValueError, match=r"names gives 32 names but the file has 31 columns"):
        fl.load(p, names=[f"n{k}" for k in range(32)])
    with pytest.raises(ValueError, match=r"names: name 2 is empty"):
        fl.load(p, names="t,,q")
    with pytest.raises(TypeError, match=r"names: name 2 is int"):
        fl.load(p, names=["t", 3])
    with pytest.raises(ValueError, match=r"resample = -0.01"):
        fl.load(p, resample=-0.01)
    with pytest.raises(ValueError, match=r"resample = 'fast'"):
        fl.load(p, resample="fast")
    with pytest.raises(ValueError, match=r"max_gap = nan"):
        fl.load(p, resample=True, max_gap=float("nan"))
    with pytest.raises(ValueError, match=r"max_gap = 1.0: only used with resample"):
        fl.load(p, max_gap=1.0)
    with pytest.raises(ValueError, match=r"resample = 100 s is longer than the record"):
        fl.load(p, resample=100)
    with pytest.raises(ValueError, match=r"names: names the columns of a CSV file"):
        fl.load(source_dir / "data" / "emps" / "DATA_EMPS.mat", names="a,b")


def test_load_mat_corrupt_compressed_variable_and_wrong_shapes(tmp_path, source_dir):
    import struct
    import zlib

    b = bytearray((source_dir / "data" / "emps" / "DATA_EMPS.mat").read_bytes())
    at = 128
    while at + 8 <= len(b):  # flip bytes in the middle of qm's compressed element
        typ, size = struct.unpack("<II", b[at:at + 8])
        head = zlib.decompressobj().decompress(bytes(b[at + 8:at + 8 + size]), 64) if typ == 15 else b""
        if head[44:48] == b"qm\0\0":
            for k in range(4):
                b[at + 8 + size // 2 + 7 * k] ^= 0x5A
        at += 8 + size
    bad = tmp_path / "flipped.mat"
    bad.write_bytes(bytes(b))
    with pytest.raises(ValueError, match=r"flipped.mat: .*variable 'qm'.*corrupt"):
        fl.load(bad)

    scipy_io = pytest.importorskip("scipy.io")
    p = tmp_path / "odd.mat"
    scipy_io.savemat(p, {"t": np.arange(20) * 1e-3, "qm": np.ones((3, 4)), "label": "rig 3",
                         "info": {"rate": 100.0}, "z": np.ones(20) * (1 + 2j)})
    d = fl.load(p)
    assert "t" in d.columns
    with pytest.raises(KeyError, match=r"variable 'qm' is a 3x4 matrix; expected a real numeric vector"):
        d["qm"]
    with pytest.raises(KeyError, match=r"variable 'info' is a 1x1 struct \(fields: rate\)"):
        d["info"]
    with pytest.raises(KeyError, match=r"variable 'z' is a 1x20 complex vector"):
        d["z"]
    assert "char array" in d.unusable["label"]


def test_import_does_not_load_matio_until_a_mat_file_is_read(source_dir):
    # matio brings HDF5, curl, GnuTLS, ... (about 30 libraries): `import frictionlab` must not pay
    # for them; the first MAT file loads them. A fresh interpreter, as pytest's has read MAT files.
    import subprocess
    import sys

    code = ("import frictionlab as fl\n"
            "maps = lambda: open('/proc/self/maps').read()\n"
            "assert 'libfrictionlab' in maps(), 'the check would pass for the wrong reason'\n"
            "assert 'libmatio' not in maps() and 'libhdf5' not in maps(), 'import loaded matio'\n"
            "fl.load(sys.argv[1])\n"
            "assert 'libmatio' in maps(), 'reading a MAT file did not load matio'\n")
    mat = source_dir / "data" / "emps" / "DATA_EMPS.mat"
    r = subprocess.run([sys.executable, "-c", "import sys\n" + code, str(mat)], capture_output=True, text=True,
                       env=dict(os.environ, PYTHONPATH=os.pathsep.join(sys.path)))
    assert r.returncode == 0, r.stderr


def test_eval_derived_columns_as_the_command_line_takes_them(tmp_path, emps):
    p = tmp_path / "joint.csv"
    p.write_text("time,TorqueCur1,Torque1,Current [A]\n0,5,1,1\n1,6,2.5,2\n2,7.5,3,4\n")
    d = fl.load(p)
    # Exact in double: sums of small binary fractions.
    np.testing.assert_array_equal(d.eval("TorqueCur1 - Torque1"), [4.0, 3.5, 4.5])
    np.testing.assert_array_equal(d.eval("-(TorqueCur1 - Torque1) / 2 + 2 * `Current [A]`"), [0.0, 2.25, 5.75])
    # Columns as they are now: scaled in numpy first.
    d["Torque1"] = d["Torque1"] * 2
    np.testing.assert_array_equal(d.eval("TorqueCur1 - Torque1"), [3.0, 1.0, 1.5])
    # A MAT file's scalar: the EMPS drive force gtau * vir.
    f = emps.eval("gtau * vir")
    np.testing.assert_allclose(f, emps["gtau"] * emps["vir"], rtol=0, atol=0)
    with pytest.raises(ValueError, match=r"joint.csv: no column 'Torq1' \(expression 'TorqueCur1 - Torq1'\)"):
        d.eval("TorqueCur1 - Torq1")
    with pytest.raises(ValueError, match="the backquote at character 1 is not closed"):
        d.eval("`Current [A]")
    with pytest.raises(ValueError, match=r"line 2: expression 'TorqueCur1 / \(Torque1 - 2\)' is inf"):
        d.eval("TorqueCur1 / (Torque1 - 2)")
    with pytest.raises(TypeError, match="expression: expected a str"):
        d.eval(3)
