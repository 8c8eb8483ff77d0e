#!/usr/bin/env bash
# identify sweep and breakaway with --load COLUMN, on records made here with numpy (independent of
# the library): a sweep at four speeds per direction run at three loads (friction
# 0.1 + 0.01 |load| N m while sliding, viscous 0.002 N m s/rad), and four torque trapezoids from rest
# at 5 to 60 N m of load (static 0.3 + 0.01 |load|, Coulomb 0.2 + 0.005 |load| N m). The
# acceptance: mu_load, the zero-load levels within a few percent, the law file carrying the load
# coefficients; a missing load column names --load and lists the file's columns, exit 2.
source "$(dirname "$0")/lib.sh"
cd "$tmp"
/usr/bin/python3 "$src/tests/rigs/load_sweep_log.py" sweep.csv --seed 7
/usr/bin/python3 - <<'PY'
import numpy as np
rng = np.random.default_rng(7)
# Breakaway: one trapezoid per load (10 integration steps per 1 ms sample, explicit stick rule).
t, v, f, l = [], [], [], []
vel, dt = 0.0, 1e-3
for load in (5.0, 20.0, 40.0, 60.0):
    peak = 1.5 * (0.3 + 0.01 * load) + 0.2
    for k in range(4500):
        s = k * dt
        u = 0.0 if s < 0.5 else peak * (s - 0.5) if s < 1.5 else peak if s < 2.5 else peak * (3.5 - s) if s < 3.5 else 0.0
        for _ in range(10):
            h = dt / 10
            if vel == 0.0:
                if abs(u) > 0.3 + 0.01 * load:
                    vel = h * (u - np.copysign(0.2 + 0.005 * load, u)) / 0.01
            else:
                nxt = vel + h * (u - np.copysign(0.2 + 0.005 * load, vel) - 0.02 * vel) / 0.01
                vel = 0.0 if (nxt > 0) != (vel > 0) else nxt
        f.append(u + 1e-3 * rng.standard_normal()); v.append(vel + 1e-4 * rng.standard_normal()); l.append(load + 0.05 * rng.standard_normal())
t = dt * np.arange(len(v))
np.savetxt("trapezoids.csv", np.column_stack([t, v, f, l]), delimiter=",", header="time,velocity,torque,load", comments="", fmt="%.9g")
PY

"$exe" identify sweep sweep.csv --force torque --model coulomb-viscous --load load --json sweep.json > sweep.txt
grep -q "mu_load" sweep.txt || { cat sweep.txt; fail "the text lacks mu_load"; }
# 24 levels of 1.2 s each: mu_load and the zero-load Coulomb level within 1 %.
check_parameters sweep.json "$(rel mu_load 0.01 0.01) and $(rel Fc 0.1 0.01) and $(rel Fv 0.002 0.05)"
/usr/bin/python3 -c "import json; j=json.load(open('sweep.json')); assert j['law']['mu_load'] == j['parameters']['mu_load']['value'], j['law']" \
  || fail "the sweep's law lacks mu_load"

"$exe" identify breakaway trapezoids.csv --force torque --load load --json brk.json > brk.txt
# The sliding fit within 2 %, the breakaway levels (4 starts) within 5 %.
check_parameters brk.json "$(rel Fc 0.2 0.02) and $(rel mu_load_coulomb 0.005 0.02) and $(rel Fs 0.3 0.05) and $(rel mu_load_static 0.01 0.05)"

# Bad input: the missing column names the flag and lists the file's columns; exit 2.
expect_fail "no column 'weight' (--load); the file has columns: " identify sweep sweep.csv --force torque --load weight
expect_fail "time, velocity, torque, load" identify breakaway trapezoids.csv --force torque --load weight
echo "PASS identify_load_column"
