"""Python bindings of the friction laws: construction, evaluation on numpy arrays, errors."""
import math

import numpy as np
import pytest

import frictionlab as fl

REL_TOL = 1e-12  # same double arithmetic as C++: only rounding differs


def test_names_cover_issue_list():
    names = fl.law_names()
    for n in ["coulomb", "viscous", "coulomb-viscous", "static-coulomb-viscous", "stribeck", "karnopp", "table",
              "dahl", "lugre", "elastoplastic", "gms", "stribeck-asymmetric", "coulomb-viscous-asymmetric"]:
        assert n in names


def test_stribeck_on_arrays():
    law = fl.FrictionLaw({"law": "stribeck", "Fc": 1.0, "Fs": 1.5, "vs": 0.001, "Fv": 0.4})
    v = np.array([-0.002, 0.001, 0.01])
    expected = [np.sign(x) * (1.0 + 0.5 * math.exp(-(abs(x) / 0.001) ** 2)) + 0.4 * x for x in v]
    np.testing.assert_allclose(law.sliding(v), expected, rtol=REL_TOL)
    assert law.breakaway == (1.5, 1.5)
    # Stuck: balances the applied force up to Fs.
    np.testing.assert_allclose(law.force(np.zeros(3), np.array([0.3, -1.2, 7.0])), [0.3, -1.2, 1.5], rtol=REL_TOL)


def test_lugre_step_reaches_stribeck_level():
    law = fl.FrictionLaw({"law": "lugre", "sigma0": 1e5, "sigma1": 316.2, "sigma2": 0.4, "Fc": 1, "Fs": 1.5, "vs": 0.001})
    force, z = law.step(np.full(2000, 0.01), 1e-3)
    assert law.is_dynamic and law.num_states == 1
    assert force[-1] == pytest.approx(1.0 + 0.5 * math.exp(-100) + 0.4 * 0.01, rel=1e-9)
    assert len(z) == 1


def test_errors_are_value_errors_with_the_library_message():
    with pytest.raises(ValueError, match=r"stribeck: vs = -1 must be > 0"):
        fl.FrictionLaw({"law": "stribeck", "Fc": 1, "Fs": 1.5, "vs": -1, "Fv": 0})
    with pytest.raises(ValueError, match="unknown friction law 'nope'; valid laws: coulomb"):
        fl.FrictionLaw({"law": "nope"})
    with pytest.raises(ValueError, match="missing parameter 'Fs'"):
        fl.FrictionLaw({"law": "stribeck", "Fc": 1, "vs": 0.1, "Fv": 0})
    with pytest.raises(ValueError, match="static"):
        fl.FrictionLaw({"law": "coulomb", "Fc": 1}).step(np.zeros(3), 1e-3)


def test_a_bristle_law_too_stiff_for_a_double_is_refused():
    # sigma0 1e308 once gave -inf friction at 10 m/s: sigma0 / Fc beyond 1e150 is refused naming sigma0.
    with pytest.raises(ValueError, match=r"lugre: sigma0 = 1e\+308 \(N/m or N m/rad\) is too stiff for Fc = 1"):
        fl.FrictionLaw({"law": "lugre", "sigma0": 1e308, "sigma1": 316.2, "sigma2": 0.4, "Fc": 1, "Fs": 1.5,
                        "vs": 0.001})
    law = fl.FrictionLaw({"law": "lugre", "sigma0": 1e9, "sigma1": 316.2, "sigma2": 0.4, "Fc": 1, "Fs": 1.5,
                          "vs": 0.001})
    assert math.isfinite(law.sliding(10.0))


def test_repr_and_round_trip():
    law = fl.FrictionLaw({"law": "coulomb-viscous", "Fc": 2.0, "Fv": 0.5})
    assert repr(law) == "FrictionLaw('coulomb-viscous', Fc=2, Fv=0.5)"
    assert fl.FrictionLaw(law.to_dict()).parameters == {"Fc": 2.0, "Fv": 0.5}


def test_units_call_pickle_and_equality():
    import pickle

    law = fl.FrictionLaw({"law": "coulomb-viscous", "Fc": 2.0, "Fv": 0.5})
    assert law.units("rotary") == {"Fc": "N m", "Fv": "N m s/rad"}
    assert law.units() == {"Fc": "N", "Fv": "N s/m"}
    np.testing.assert_allclose(law(np.array([-1.0, 2.0])), [-2.5, 3.0], rtol=REL_TOL)
    assert pickle.loads(pickle.dumps(law)) == law
    assert law != fl.FrictionLaw({"law": "coulomb-viscous", "Fc": 2.0, "Fv": 0.6})
    table = fl.FrictionLaw({"law": "table", "velocity": np.array([0.1, 1.0]), "force": [1.0, 2.0]})
    assert table.sliding(0.55) == pytest.approx(1.5, rel=REL_TOL)


def test_bad_dict_values():
    with pytest.raises(ValueError, match="law parameter 'Fc': expected a number or a list of numbers"):
        fl.FrictionLaw({"law": "coulomb", "Fc": True})
    with pytest.raises(ValueError, match="law parameter 'Fc': expected a number or a list of numbers"):
        fl.FrictionLaw({"law": "coulomb", "Fc": object()})
    with pytest.raises(ValueError, match=r"missing 'law' \(one of frictionlab.law_names\(\)\)"):
        fl.FrictionLaw({"Fc": 1})
    with pytest.raises(ValueError, match="axis"):
        fl.FrictionLaw({"law": "coulomb", "Fc": 1}).units("diagonal")
    with pytest.raises(ValueError, match="v: expected a 1-D array of numbers"):
        fl.FrictionLaw({"law": "dahl", "sigma0": 1e5, "Fc": 1}).step(np.zeros((2, 2)), 1e-3)
