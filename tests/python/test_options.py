"""The Python keywords of the identification methods come from their option tables (the library's,
frictionlab/identify/method.hpp): each keyword is the command line's flag name (snake_case), a
former keyword still works with a DeprecationWarning and gives the same result, an unknown one is a
TypeError, values are checked by the table (ValueError naming the option), the docstrings list
the table, and a result records the options that shaped it (its JSON "options")."""
import json
import re
import subprocess
import warnings

import numpy as np
import pytest

import frictionlab as fl


def sweep_record():
    """A rotary axis run at five speed levels each way (2 s each, 1 kHz) through a Coulomb +
    viscous law (Fc = 0.1 N m, Fv = 0.01 N m s/rad) with a little seeded noise."""
    rng = np.random.default_rng(3)
    levels = [5, 10, 20, 40, 80, -5, -10, -20, -40, -80]
    t = np.arange(len(levels) * 2000) * 1e-3
    v = np.repeat(levels, 2000).astype(float) + 0.01 * rng.standard_normal(t.size)
    f = 0.1 * np.sign(v) + 0.01 * v + 1e-4 * rng.standard_normal(t.size)
    return t, f, v


def table(method):
    return {o["keyword"]: o for o in {m.name: m for m in fl.methods()}[method].options}


def test_keywords_are_the_command_line_names():
    for m in fl.methods():
        for o in m.options:
            assert o["keyword"].rstrip("_") == o["name"].replace("-", "_"), (m.name, o)
    assert set(table("idim")) >= {"vs", "delay", "decimate", "cutoff", "delta", "terms", "from_"}
    assert table("idim")["vs"]["deprecated"] == ["stribeck_vs"]
    assert table("idim")["delay"]["deprecated"] == ["input_delay"]
    assert table("idim")["decimate"]["deprecated"] == ["decimation"]
    # The default the docs give is the library's (1e-6 of the largest |v|, computed: no number).
    assert table("sweep")["min_speed"]["default"] is None
    assert "1e-6 of the largest |velocity|" in table("sweep")["min_speed"]["help"]
    assert table("sweep")["min_duration"]["default"] == "0.5"


def test_docstrings_list_the_option_table():
    for function, method in ((fl.identify_sweep, "sweep"), (fl.identify_idim, "idim"), (fl.identify_lugre, "lugre"),
                             (fl.identify_breakaway, "breakaway"), (fl.identify_decay, "decay")):
        for keyword, o in table(method).items():
            assert f"      {keyword}: {o['help']}" in function.__doc__, (method, keyword)
    assert "1e-3 max" not in fl.identify_sweep.__doc__  # the drifted default of the former docstring


def _python_words(cli_text, method):
    """The CLI's "applies ..." text as a docstring says it: keywords for flags, a flag True or
    False, any other option given or not, words as Python strings (the same conditions)."""
    options = {o["name"]: o for o in {m.name: m for m in fl.methods()}[method].options}
    parts = []
    for part in cli_text[len("applies "):].split(" and "):
        m = re.fullmatch(r"(with|without) --([\w-]+)", part)
        if m:
            o = options[m.group(2)]
            if o["type"] == "flag":
                parts.append(f"with {o['keyword']}={m.group(1) == 'with'}")
            else:
                parts.append(f"when {o['keyword']} is {'given' if m.group(1) == 'with' else 'not given'}")
            continue
        m = re.fullmatch(r"when --([\w-]+) (holds|is|does not hold|is not) (.+)", part)
        assert m, part
        words = re.split(r", | or ", m.group(3))
        quoted = [f"'{w}'" for w in words]
        listed = quoted[0] if len(quoted) == 1 else ", ".join(quoted[:-1]) + " or " + quoted[-1]
        parts.append(f"when {options[m.group(1)]['keyword']} {m.group(2)} {listed}")
    return "applies " + " and ".join(parts)


def test_docstrings_say_when_an_option_applies_as_the_command_line(cli):
    """help(fl.identify_idim) says "applies with iv=True" where `frictionlab help` says "applies
    with --iv": both from the table's conditions, for every option of every method."""
    text = subprocess.run([cli, "help"], capture_output=True, text=True, check=True).stdout
    cli_applies, method = {}, None
    for line in text.splitlines():
        if not line.startswith(" "):
            method = line.split(":", 1)[0]
        elif line.startswith("  --"):
            name = line[4:].split(" ", 1)[0]
            at = line.rfind("(applies ")
            cli_applies[(method, name)] = line[at + 1:-1] if at >= 0 and line.endswith(")") else ""
    functions = {m.name: getattr(fl, m.function) for m in fl.methods() if m.function and m.function.startswith("identify_")}
    assert set(functions) >= {"idim", "sweep", "lugre", "auto", "breakaway", "decay"}
    conditional = 0
    for method, function in functions.items():
        doc = function.__doc__.splitlines()
        for o in table(method).values():
            line = next(x for x in doc if x.startswith(f"      {o['keyword']}: "))
            m = re.search(r"(?:\[|; )(applies [^;\]]*)\]$", line)
            shown = m.group(1) if m else ""
            expected = cli_applies[(method, o["name"])]
            assert shown == (_python_words(expected, method) if expected else ""), (method, o["name"], line, expected)
            conditional += bool(expected)
    assert conditional >= 20  # idim's IV, Stribeck, ripple, load, temperature options; sweep's; lugre's; auto's
    doc = fl.identify_idim.__doc__
    assert re.search(r"\n      kp: .*applies with iv=True\]\n", doc)
    assert re.search(r"\n      vs: .*applies when terms holds 'stribeck'\]\n", doc)
    assert "applies when segment is not given and when reference is not given]" in fl.identify_sweep.__doc__


def test_deprecated_keywords_warn_and_give_the_same_result():
    t, f, v = sweep_record()
    new = fl.identify_sweep(t, f, v, model="coulomb-viscous", tolerance=0.02, segment=[(1, 1.9), (3, 3.9), (5, 5.9)])
    with pytest.warns(DeprecationWarning, match="keyword 'relative_tolerance' is deprecated; use 'tolerance'"):
        old = fl.identify_sweep(t, f, v, model="coulomb-viscous", relative_tolerance=0.02,
                                windows=[(1, 1.9), (3, 3.9), (5, 5.9)])
    assert new.ok and old.ok
    assert new.to_dict()["parameters"] == old.to_dict()["parameters"]
    # The record names the option by its table name, however the caller spelled it.
    assert json.loads(new.to_json())["options"] == json.loads(old.to_json())["options"]


def test_new_keywords_need_no_warning():
    t, f, v = sweep_record()
    with warnings.catch_warnings():
        warnings.simplefilter("error", DeprecationWarning)
        r = fl.identify_sweep(t, f, v, model="coulomb-viscous", min_duration=1.0, min_speed=0.1, axis="rotary")
    assert r.ok, r.message
    options = json.loads(r.to_json())["options"]
    assert options["min-duration"] == {"value": 1.0, "unit": "s", "given": True}
    assert options["min-speed"] == {"value": 0.1, "unit": "rad/s", "given": True}
    assert options["model"]["value"] == "coulomb-viscous"
    assert json.loads(r.to_json())["frictionlab"]["version"] == fl.__version__


def test_unknown_twice_and_missing_keywords_are_type_errors():
    t, f, v = sweep_record()
    with pytest.raises(TypeError, match="identify_sweep\\(\\) got an unexpected keyword argument 'min_durations'"):
        fl.identify_sweep(t, f, v, min_durations=1.0)
    with pytest.raises(TypeError, match="got the option 'tolerance' twice"):
        fl.identify_sweep(t, f, v, tolerance=0.01, relative_tolerance=0.02)
    with pytest.raises(TypeError, match="missing required keyword argument: 'inertia'"):
        fl.identify_lugre(t, f, v)


def test_values_are_checked_by_the_table():
    t, f, v = sweep_record()
    with pytest.raises(ValueError, match=r"sweep: min_duration \(--min-duration\) = -1 must be > 0 \(s\)"):
        fl.identify_sweep(t, f, v, min_duration=-1)
    with pytest.raises(ValueError, match="sweep: settle_fraction \\(--settle-fraction\\) = 1 must be >= 0 and < 1"):
        fl.identify_sweep(t, f, v, settle_fraction=1)
    with pytest.raises(ValueError, match=r"idim: vs \(--vs\) 'fast': expected a Stribeck velocity \(m/s or rad/s\) or 'search'"):
        fl.identify_idim(t, f, position=v, vs="fast")
    with pytest.raises(ValueError, match=r"idim: delay \(--delay\) = -1 must be >= 0"):
        fl.identify_idim(t, f, position=v, delay=-1)
    with pytest.raises(ValueError, match=r"breakaway: edge_samples \(--edge-samples\) 2.5: expected an integer >= 0"):
        fl.identify_breakaway(t, f, v, edge_samples=2.5)


def test_idim_new_and_old_keywords_agree(emps):
    force = emps["gtau"] * emps["vir"]
    new = fl.identify_idim(emps["t"], force, emps["qm"], terms="inertia,asymmetric,stribeck", delay=1, vs=0.02)
    with pytest.warns(DeprecationWarning):
        old = fl.identify_idim(emps["t"], force, emps["qm"], terms="inertia,asymmetric,stribeck", input_delay=1,
                               stribeck_vs=0.02)
    assert new.ok and old.ok
    assert new.to_dict()["parameters"] == old.to_dict()["parameters"]
    options = json.loads(new.to_json())["options"]
    assert options["delay"] == {"value": 1, "unit": "samples", "given": True}
    assert options["vs"] == {"value": 0.02, "unit": "m/s", "given": True}
    # result.options is the same record, by the command line's names (not the library's
    # input_delay, stribeck_vs): one name per option everywhere a user reads it.
    assert new.options == options and old.options == options
    assert "stribeck_vs" not in new.options and "input_delay" not in new.options
    # The fit's own options still serve the reconstruction and the cross-test.
    assert fl.cross_test(new, emps["t"], force, emps["qm"]).relative_error_percent == pytest.approx(
        new.fit.relative_error_percent, rel=1e-9)


def test_recorded_unit_is_the_one_the_run_decides(emps):
    """An option whose unit the controller's type decides is recorded in the run's unit: kp in
    1/s with controller="emps-pd" (N/m with pid), as the command line's report and JSON give it."""
    force = emps["gtau"] * emps["vir"]
    r = fl.identify_idim(emps["t"], force, position=emps["qm"], source=emps, iv=True, controller="emps-pd",
                         kp="kp", kv="kv", drive_gain="gtau", reference=emps["qg"])
    assert r.ok, r.message
    options = json.loads(r.to_json())["options"]
    assert options["kp"] == {"value": 160.18, "unit": "1/s", "given": True}
    assert options["control-limit"]["unit"] == "V"
    plain = json.loads(fl.identify_idim(emps["t"], force, position=emps["qm"]).to_json())["options"]
    assert plain["kp"]["unit"] == "N/m or 1/s"  # nothing decides it: both named


def test_sweep_refuses_irregular_time_like_every_method():
    t, f, v = sweep_record()
    t = t.copy()
    t[5000] += 0.5e-3  # half a step late
    with pytest.raises(ValueError, match="sweep: sample .*regularly sampled"):
        fl.identify_sweep(t, f, v)
