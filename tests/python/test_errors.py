"""frictionlab.Error: bad input with a stable code raises a ValueError subclass carrying .code and
the fields that locate the fault (file, row, column, key, option, value; None when they do not
apply)."""
import pytest

import frictionlab as fl


def test_error_is_a_value_error():
    assert issubclass(fl.Error, ValueError)


def test_csv_text_cell_code_and_fields(tmp_path):
    p = tmp_path / "d.csv"
    p.write_text("time,position\n0,0\n0.001,abc\n")
    with pytest.raises(fl.Error) as info:
        fl.load(str(p))
    e = info.value
    assert e.code == "data.not_a_number"
    assert e.file == str(p)
    assert e.row == 3
    assert e.column == "position"
    assert e.value == "abc"
    assert e.key is None and e.option is None
    assert "line 3" in str(e)  # the message is unchanged


def test_missing_file_is_still_a_value_error(tmp_path):
    with pytest.raises(ValueError) as info:
        fl.load(str(tmp_path / "none.csv"))
    assert isinstance(info.value, fl.Error)
    assert info.value.code == "data.file_unreadable"


def test_scenario_unknown_key(tmp_path):
    p = tmp_path / "s.yaml"
    p.write_text("plant: {type: pendulum, m: 1, l: 1, colour: red}\nfriction: {law: coulomb, Fc: 0.1}\nduration: 1\n")
    with pytest.raises(fl.Error) as info:
        fl.Scenario.load(str(p))
    assert info.value.code == "scenario.key_unknown"
    assert info.value.key == "plant.colour"
    assert info.value.file == str(p)


def test_law_file_value(tmp_path):
    p = tmp_path / "law.json"
    p.write_text('{"law": "coulomb", "Fc": "one"}')
    with pytest.raises(fl.Error) as info:
        fl.load_law(str(p))
    assert info.value.code == "scenario.value"
    assert info.value.key == "Fc"


def test_not_utf8_message_does_not_break_the_exception(tmp_path):
    p = tmp_path / "d.csv"
    p.write_bytes(b"time,pos\xe9\n0,0\n0.001,abc\n")
    with pytest.raises(fl.Error) as info:
        fl.load(str(p))
    assert info.value.code == "data.not_a_number"
    assert info.value.row == 3
