"""decay_envelope and detect_stick_slip on Craig's pendulum cases and exact stick-slip."""
import numpy as np
import pytest

import frictionlab as fl


@pytest.mark.parametrize("case, kind", [("craig_pendulum_coulomb", "linear"), ("craig_pendulum_viscous", "exponential"),
                                        ("craig_pendulum_frictionless", "none")])
def test_envelope_kind_of_pendulum_cases(example, case, kind):
    tr = fl.simulate(example(case))
    e = fl.decay_envelope(tr["time"], tr["position"])
    assert e.kind == kind
    assert len(e.amplitudes) == len(e.peak_times) >= 3
    # Small-angle period of a 1 m pendulum: pi sqrt(l/g) per half cycle, within 2 %.
    assert e.half_period == pytest.approx(np.pi * np.sqrt(1 / 9.81), rel=0.02)


def test_envelope_fit_and_errors(example):
    tr = fl.simulate(example("craig_pendulum_viscous"))
    e = fl.decay_envelope(tr)
    # Viscous pivot friction: the exponential envelope through every half swing.
    np.testing.assert_allclose(e.envelope(e.peak_times), e.amplitudes, rtol=0.02)
    np.testing.assert_allclose(e.envelope(e.peak_times, "exponential"), e.envelope(e.peak_times), rtol=1e-15)
    with pytest.raises(ValueError, match="envelope kind 'cubic': expected linear, exponential or mixed"):
        e.envelope(e.peak_times, "cubic")
    assert e.log_decrement > 0 and e.fit.lambda_ == e.exponential.lambda_
    t = np.linspace(0, 1, 50)
    with pytest.raises(ValueError, match=r"decay envelope: found 0 half cycles; need at least 4 to fit an envelope"):
        fl.decay_envelope(t, t)
    with pytest.raises(ValueError, match="decay envelope: time has 50 samples but position has 49; expected equal lengths"):
        fl.decay_envelope(t, t[:-1])


def test_stick_slip_exact_and_errors(example):
    tr = fl.simulate(example("craig_stick_slip"))
    s = fl.detect_stick_slip(tr["time"], tr["velocity"], tr["friction"])
    assert len(s.slip) >= 3 and s.stick.shape[1] == 2
    assert s.velocity_threshold == 0.0  # exact zeros of the hybrid engine
    assert s.mean_force_drop > 0 and len(s.breakaway_force) == len(s.restick_force)
    no_force = fl.detect_stick_slip(tr["time"], tr["velocity"])
    assert len(no_force.breakaway_force) == 0 and no_force.period == s.period
    with pytest.raises(ValueError, match="negative|threshold"):
        fl.detect_stick_slip(tr["time"], tr["velocity"], velocity_threshold=-1)
    with pytest.raises(ValueError, match="length|differ"):
        fl.detect_stick_slip(tr["time"], tr["velocity"][:-1])
