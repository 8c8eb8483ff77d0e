"""Figures with matplotlib, the same as the command line's --plot:

  sweep(result)        friction-velocity map: points with error bars and the fitted law
  idim(result)         measured vs reconstructed force (and the residual)
  breakaway(result)    the applied force of a breakaway ramp with Fs and the Coulomb level Fc
  lugre(result)        the steady-state friction map of an identified LuGre law
  simulation(traj)     time series of a simulation
  decay(t, x)          free decay with its peaks and the fitted envelope
  contour(result)      a circular test's radial error against the angle, quadrant glitches marked
  map(rows)            a map of motion classes over one or two scenario keys (fl.analyze_map)
  drift(table)         a fleet's parameters with their std against the log's date, flagged changes marked
  load_map(result)     an idim fit with the load term: friction against velocity in three bands of |load|
  ripple(result)       an idim fit with the ripple term: the ripple against the position within its period
  temperature(result)  an idim fit with the temperature term: the logged temperature and the viscous coefficient

Every function takes ``ax=``: the matplotlib Axes to draw into (a sequence of Axes, one per panel,
for the figures of several panels: idim 2, decay 2, temperature 2, simulation and drift one per
column or parameter); it then returns that Axes (or the list) and leaves the layout to the caller. Without
``ax`` it makes a figure and returns the Figure; ``file=`` writes it (format by the extension).

Every axis label carries its unit; a log-spaced map axis is drawn on a logarithmic scale; legends
sit beside the axes (right of them), never over data, tick labels or axis labels.
matplotlib is imported here only, so ``import frictionlab`` does not need it.
"""
import numpy as np

from .analysis import decay_envelope
from .methods.idim import idim_reconstruction

# Force unit -> velocity unit of the same axis, for labels.
_VELOCITY_UNIT = {"N": "m/s", "N m": "rad/s"}
# Units of a simulation's columns by axis ('linear', 'rotary'; None: either).
_UNITS = {
    "linear": {"position": "m", "velocity": "m/s", "acceleration": "m/s^2", "force": "N"},
    "rotary": {"position": "rad", "velocity": "rad/s", "acceleration": "rad/s^2", "force": "N m"},
    None: {"position": "m or rad", "velocity": "m/s or rad/s", "acceleration": "m/s^2 or rad/s^2", "force": "N or N m"},
}
# A simulation column's quantity, by its name's last part (x.position -> position).
_QUANTITY = {"position": "position", "velocity": "velocity", "acceleration": "acceleration", "friction": "force",
             "applied": "force", "force": "force", "drive": "force", "current": None, "z": "position"}
_COLUMN_EXTRA_UNITS = {"current": "A", "time": "s", "stuck": "-", "mode": "-"}
_CLASS_COLOURS = {"converged": "#009e73", "steady-sliding": "#0072b2", "stick-slip": "#d55e00", "hunting": "#cc79a7",
                  "oscillating": "#e69f00", "failed": "#000000"}


def _axes(ax, n, figsize):
    """(figure or None, list of n Axes): the caller's (ax: an Axes for n = 1, else n Axes) or new ones."""
    if ax is None:
        import matplotlib.pyplot as plt

        fig, axes = plt.subplots(n, 1, figsize=figsize, sharex=True, squeeze=False)
        return fig, list(axes[:, 0])
    axes = [ax] if n == 1 and not isinstance(ax, (list, tuple, np.ndarray)) else list(np.ravel(ax))
    if len(axes) != n:
        raise ValueError(f"ax: this figure has {n} panel{'s' if n > 1 else ''}; got {len(axes)} Axes")
    return None, axes


def _done(fig, axes, file, single):
    """The Figure (made here; laid out, written to `file`) or the caller's Axes (or list)."""
    if fig is None:
        if file is not None:
            axes[0].figure.savefig(file)
        return axes[0] if single else axes
    fig.tight_layout()
    if file is not None:
        fig.savefig(file, dpi=100)
    return fig


def _legend(ax, **kw):
    """A legend beside the axes, right of them: clear of the data and of every label."""
    if ax.get_legend_handles_labels()[0]:
        ax.legend(loc="upper left", bbox_to_anchor=(1.01, 1.0), borderaxespad=0.0, **kw)


def _force_unit(result):
    units = result.units
    for name in ("Fc", "Fc_pos", "offset", "Fs"):
        if name in units:
            return units[name]
    return "N m" if getattr(result, "axis", "linear") == "rotary" else "N"


def _column_label(name, axis):
    last = name.rsplit(".", 1)[-1]
    if last in _COLUMN_EXTRA_UNITS:
        return f"{name} ({_COLUMN_EXTRA_UNITS[last]})"
    q = _QUANTITY.get(last, "")
    if q:
        return f"{name} ({_UNITS[axis][q]})"
    return f"{name} (scenario units, SI)"


def _friction_axes(a, fu, title):
    """Labels (velocity and friction in the force unit fu's axis), title, grid and legend of a
    friction-velocity panel."""
    a.set_xlabel(f"velocity ({_VELOCITY_UNIT.get(fu, 'm/s')})")
    a.set_ylabel(f"friction ({fu})")
    a.set_title(title)
    a.grid(True, alpha=0.3)
    _legend(a)


def sweep(result, *, ax=None, file=None, title=None):
    """Friction-velocity map of a sweep result: segment means with ±1 std error bars, and the
    fitted law over the measured velocity range. Returns the Figure (or ``ax``)."""
    points = result.diagnostics.lists.get("points", [])
    if not points:
        raise ValueError("sweep plot: the result has no points (diagnostics.lists['points'])")
    v = np.array([p["velocity"] for p in points])
    f = np.array([p["force"] for p in points])
    fig, (a,) = _axes(ax, 1, (9, 4.5))
    a.errorbar(v, f, xerr=[p["velocity_std"] for p in points], yerr=[p["force_std"] for p in points], fmt="o",
               ms=4, capsize=3, label="steady segments")
    law = result.law
    if law is not None:
        lo, hi = min(v.min(), 0.0), max(v.max(), 0.0)
        grid = np.concatenate([np.linspace(lo, -1e-9 * (hi - lo), 300) if lo < 0 else [],
                               np.linspace(1e-9 * (hi - lo), hi, 300) if hi > 0 else []])
        a.plot(grid, law.sliding(grid), "-", label=f"fitted {law.name}")
    _friction_axes(a, _force_unit(result),
                   title or f"sweep: {result.model}, relative error {result.fit.relative_error_percent:.3g} %")
    return _done(fig, [a], file, True)


def idim(result, *, ax=None, file=None, title=None):
    """Measured vs reconstructed force of an idim result (decimated samples), and the residual.
    ``ax``: two Axes (force, residual). Returns the Figure (or the two Axes)."""
    rec = idim_reconstruction(result)
    fu = _force_unit(result)
    fig, (a, a_res) = _axes(ax, 2, (9, 6))
    a.plot(rec["time"], rec["measured"], "-", lw=1, label="measured")
    a.plot(rec["time"], rec["reconstructed"], "--", lw=1, label="reconstructed")
    a.set_ylabel(f"force ({fu})")
    a.set_title(title or f"idim: {result.model}, relative error {result.fit.relative_error_percent:.3g} %")
    _legend(a)
    a.grid(True, alpha=0.3)
    a_res.plot(rec["time"], rec["residual"], "-", lw=0.8, color="tab:red")
    a_res.set_ylabel(f"residual ({fu})")
    a_res.set_xlabel("time (s)")
    a_res.grid(True, alpha=0.3)
    return _done(fig, [a, a_res], file, False)


def breakaway(result, *, ax=None, file=None, title=None):
    """A breakaway experiment (identify_breakaway): the applied force against time, the breakaway
    (Fs, at its time) and the Coulomb level Fc. Returns the Figure (or ``ax``)."""
    s = result.series
    if "time" not in s or "force" not in s:
        raise ValueError("breakaway plot: the result has no 'time' and 'force' series (not a breakaway result?)")
    fu = _force_unit(result)
    fig, (a,) = _axes(ax, 1, (9, 4.5))
    t, F = s["time"], s["force"]
    a.plot(t, F, "-", lw=1.2, label="applied")
    tb = result.diagnostics.numbers.get("breakaway_time")
    if "Fs" in result and tb is not None and np.isfinite(result["Fs"]):
        a.plot([tb], [result["Fs"]], "o", ms=7, color="tab:red", label="breakaway Fs")
    if "Fc" in result and np.isfinite(result["Fc"]):
        a.plot([t[0], t[-1]], [result["Fc"]] * 2, "--", color="tab:green", label="Coulomb level Fc")
    a.set_xlabel("time (s)")
    a.set_ylabel(f"applied {'torque' if fu == 'N m' else 'force'} ({fu})")
    a.set_title(title or "breakaway: applied force, Fs and Fc")
    a.grid(True, alpha=0.3)
    _legend(a)
    return _done(fig, [a], file, True)


def lugre(result, *, ax=None, file=None, title=None, vmax=None):
    """The steady-state friction of an identified LuGre law (identify_lugre) against velocity,
    over ±``vmax`` (default: 20 vs, or the record's largest speed when it has a velocity series),
    with the Stribeck velocity vs marked. Returns the Figure (or ``ax``)."""
    law = result.law
    if law is None:
        raise ValueError("lugre plot: the result has no law (status error or undetermined parameters)")
    fu = _force_unit(result)
    vs = result["vs"] if "vs" in result else 1e-3
    v_rec = result.series.get("velocity")
    top = vmax or (float(np.nanmax(np.abs(v_rec))) if v_rec is not None and len(v_rec) else 20 * vs)
    grid = np.concatenate([np.linspace(-top, -1e-9 * top, 400), np.linspace(1e-9 * top, top, 400)])
    fig, (a,) = _axes(ax, 1, (9, 4.5))
    F = law.sliding(grid)
    a.plot(grid[:400], F[:400], "-", color="tab:blue", label="steady-state friction")
    a.plot(grid[400:], F[400:], "-", color="tab:blue")
    a.plot([-vs, vs], law.sliding([-vs, vs]), "o", color="tab:green", label="v = ±vs")
    a.axhline(0, color="0.4", lw=0.8)
    a.axvline(0, color="0.4", lw=0.8)
    _friction_axes(a, fu, title or "LuGre: steady-state friction of the identified law")
    return _done(fig, [a], file, True)


def simulation(trajectory, columns=("position", "velocity", "friction"), *, axis=None, ax=None, file=None,
               title=None):
    """Time series of a simulation (a Trajectory or a dict of columns), one panel per column.
    ``axis``: 'linear' or 'rotary' for the units (default: both named, "m or rad").
    ``ax``: one Axes per column. Returns the Figure (or the Axes)."""
    if axis not in _UNITS:
        raise ValueError(f"simulation plot: axis '{axis}' must be 'linear', 'rotary' or None")
    columns = list(columns)
    fig, axes = _axes(ax, len(columns), (9, 2.2 * len(columns) + 1))
    t = np.asarray(trajectory["time"])
    for a, name in zip(axes, columns):
        a.plot(t, np.asarray(trajectory[name]), lw=1)
        a.set_ylabel(_column_label(name, axis))
        a.grid(True, alpha=0.3)
    axes[-1].set_xlabel("time (s)")
    if title:
        axes[0].set_title(title)
    return _done(fig, axes, file, False)


def decay(t, x=None, *, envelope=None, axis=None, ax=None, file=None, title=None):
    """A free decay: position with its peaks (top), and the half-swing amplitudes with the
    fitted envelope of the detected kind (bottom). ``t`` and ``x`` (s; m or rad), or a
    Trajectory / dict as ``t``. ``envelope``: an EnvelopeResult (computed when not given).
    ``axis``: 'linear' or 'rotary' for the units. ``ax``: two Axes. Returns the Figure (or the Axes)."""
    if axis not in _UNITS:
        raise ValueError(f"decay plot: axis '{axis}' must be 'linear', 'rotary' or None")
    if x is None:
        t, x = t["time"], t["position"]
    t, x = np.asarray(t, dtype=float), np.asarray(x, dtype=float)
    env = envelope if envelope is not None else decay_envelope(t, x)
    unit = _UNITS[axis]["position"]
    fig, (a, a_env) = _axes(ax, 2, (9, 6))
    a.plot(t, x, lw=1, label="position")
    peaks = env.peak_times
    a.plot(peaks, np.interp(peaks, t, x), "o", ms=4, label="extremes")
    a.set_ylabel(f"position ({unit})")
    _legend(a)
    a.grid(True, alpha=0.3)
    a.set_title(title or f"decay: {env.kind} ({len(env.amplitudes)} half cycles)")
    a_env.plot(peaks, env.amplitudes, "o", ms=4, label="half-swing amplitude")
    grid = np.linspace(peaks.min(), peaks.max(), 300) if len(peaks) else peaks
    a_env.plot(grid, env.envelope(grid), "-", label=f"{env.kind} envelope")
    a_env.set_xlabel("time (s)")
    a_env.set_ylabel(f"amplitude ({unit})")
    _legend(a_env)
    a_env.grid(True, alpha=0.3)
    return _done(fig, [a, a_env], file, False)


def contour(result, *, ax=None, file=None, title=None):
    """A circular test (analyze_contour): the radial error r - R (um) against the angle (deg),
    the quadrant glitches marked at their peaks. Returns the Figure (or ``ax``)."""
    angle = np.asarray(result.angle_deg, dtype=float)
    err = np.asarray(result.radial_error, dtype=float) * 1e6
    if angle.size == 0:
        raise ValueError("contour plot: the result has no samples")
    fig, (a,) = _axes(ax, 1, (9, 4.5))
    order = np.argsort(angle)
    a.plot(angle[order], err[order], ".", ms=2, label="radial error")
    g = result.glitches
    if g:
        a.plot([q.angle_deg for q in g], [q.peak_m * 1e6 for q in g], "v", ms=8, color="tab:red",
               label="quadrant glitches")
    a.axhline(0, color="0.4", lw=0.8)
    a.set_xlim(0, 360)
    a.set_xticks([0, 90, 180, 270, 360])
    a.set_xlabel("angle (deg)")
    a.set_ylabel("radial error r - R (um)")
    a.set_title(title or f"circular test: R = {result.radius * 1e3:.4g} mm, roundness "
                          f"{result.roundness_m * 1e6:.3g} um")
    a.grid(True, alpha=0.3)
    _legend(a)
    return _done(fig, [a], file, True)


def _is_log_spaced(values):
    u = np.unique(np.asarray(values, dtype=float))
    if u.size < 3 or u[0] <= 0:
        return False
    r = u[1:] / u[:-1]
    d = np.diff(u)
    return bool(np.allclose(r, r[0], rtol=1e-6) and not np.allclose(d, d[0], rtol=1e-6))


def map(rows, keys=None, *, units=None, ax=None, file=None, title=None):
    """A map (fl.analyze_map's rows): 2-D, each grid point's motion class as a coloured marker over
    the two keys; 1-D, the oscillation amplitude against the key, coloured by class. A key whose
    values are log-spaced (``--vary KEY=log:...``) is drawn on a logarithmic scale. ``keys``: the
    varied keys (default: the columns between 'index' and 'class'); ``units``: {key: unit} for the
    labels (default "scenario units, SI"). Returns the Figure (or ``ax``)."""
    rows = list(rows)
    if not rows:
        raise ValueError("map plot: no rows")
    cols = list(rows[0].keys())
    if keys is None:
        if "class" not in cols:
            raise ValueError("map plot: the rows have no 'class' column (not fl.analyze_map's rows?)")
        keys = [c for c in cols[: cols.index("class")] if c != "index"]
    if len(keys) not in (1, 2):
        raise ValueError(f"map plot: draws 1 or 2 keys; got {len(keys)} ({', '.join(keys)})")
    units = dict(units or {})
    label = lambda k: f"{k} ({units.get(k, 'scenario units, SI')})"  # noqa: E731
    fig, (a,) = _axes(ax, 1, (9, 5))
    xs = np.array([r[keys[0]] for r in rows], dtype=float)
    ys = (np.array([r[keys[1]] for r in rows], dtype=float) if len(keys) == 2
          else np.array([r.get("amplitude", np.nan) for r in rows], dtype=float))
    classes = [r["class"] for r in rows]
    for name in dict.fromkeys(classes):
        mine = np.array([c == name for c in classes])
        a.plot(xs[mine], np.nan_to_num(ys[mine]), "o", ms=7, color=_CLASS_COLOURS.get(name), label=name)
    if _is_log_spaced(xs):
        a.set_xscale("log")
    if len(keys) == 2 and _is_log_spaced(ys):
        a.set_yscale("log")
    a.set_xlabel(label(keys[0]))
    a.set_ylabel(label(keys[1]) if len(keys) == 2 else f"amplitude ({units.get('amplitude', 'm or rad')})")
    a.set_title(title or "map: " + " x ".join(keys))
    a.grid(True, alpha=0.3)
    _legend(a)
    return _done(fig, [a], file, True)


def drift(table, parameters=None, *, ax=None, file=None, title=None):
    """A fleet's drift: one panel per parameter, its value with ±1 std error bars against the
    log's date, the changes the drift rule flagged (frictionlab.batch.drift) circled in red.
    ``table``: a drift Table (batch.drift) or an identification Table with dates (drift is
    computed with the default threshold). ``parameters``: names to draw (default all).
    ``ax``: one Axes per parameter. Returns the Figure (or the Axes)."""
    import datetime

    from .batch import drift as drift_table

    if getattr(table, "kind", "drift") != "drift":
        table = drift_table(table)
    rows = list(table)
    if not rows:
        raise ValueError("drift plot: the table has no rows (no ok identification with a date)")
    names = list(parameters) if parameters else list(dict.fromkeys(r["parameter"] for r in rows))
    fig, axes = _axes(ax, len(names), (9, 2.2 * len(names) + 1))
    for a, name in zip(axes, names):
        mine = [r for r in rows if r["parameter"] == name]
        if not mine:
            raise ValueError(f"drift plot: no parameter '{name}' in the table")
        dates = [datetime.datetime.fromisoformat(r["date"]) for r in mine]
        values = np.array([r["value"] for r in mine], dtype=float)
        stds = np.array([np.nan if r["std"] is None else r["std"] for r in mine], dtype=float)
        a.errorbar(dates, values, yerr=np.nan_to_num(stds), fmt="o-", ms=4, capsize=3, lw=1, label="value ± std")
        flagged = [k for k, r in enumerate(mine) if r["flagged"]]
        if flagged:
            a.plot([dates[k] for k in flagged], values[flagged], "o", ms=11, mfc="none", mec="tab:red", mew=1.5,
                   label="change > threshold x combined std")
        _legend(a)
        unit = mine[0]["unit"] or "-"
        a.set_ylabel(f"{name} ({unit})")
        a.grid(True, alpha=0.3)
    axes[-1].set_xlabel("log date (UTC)")
    if fig is not None:
        fig.autofmt_xdate()
    # The number of logs, not of rows: a row is one parameter of one log.
    axes[0].set_title(title or f"drift over {len({r['file'] for r in rows})} logs")
    return _done(fig, axes, file, False)


def _condition_series(result, names, what, term):
    """The idim result's series `names` (numpy arrays), or ValueError naming the term to fit."""
    if not result.ok:
        raise ValueError(f"{what} plot: the idim result has status error: {result.message}")
    s = result.series
    missing = [n for n in names if n not in s or len(s[n]) == 0]
    if missing:
        raise ValueError(f"{what} plot: the result has no '{missing[0]}' series: fit identify_idim with the "
                         f"'{term}' term")
    return [np.asarray(s[n], dtype=float) for n in names]


def load_map(result, *, ax=None, file=None, title=None):
    """Friction against velocity and load of an idim result with the 'load' term: the friction
    map's samples (force less the inertia and offset terms) in three bands of |load| (lower,
    middle and upper third of its range; legend "|load| LO to HI"), each with the identified law at
    the band's mean |load| (legend "law at |load| MEAN"). Returns the Figure (or ``ax``). Raises ValueError on a result without the load term."""
    v, F, L = _condition_series(result, ("velocity", "friction", "load"), "load map", "load")
    fu = _force_unit(result)
    mu = result.value("mu_load")
    law_v = np.asarray(result.series.get("law_velocity", []), dtype=float)
    law_0 = np.asarray(result.series.get("law_force_zero_load", []), dtype=float)
    fig, (a,) = _axes(ax, 1, (9, 5))
    lo, hi = float(L.min()), float(L.max())
    width = max((hi - lo) / 3, 1e-300)
    band = np.minimum(2, ((L - lo) / width).astype(int))
    for b, colour in enumerate(("#0072b2", "#009e73", "#d55e00")):
        mine = band == b
        if not mine.any():
            continue
        a.plot(v[mine], F[mine], ".", ms=2, color=colour, alpha=0.5,
               label=f"|load| {lo + b * width:.3g} to {lo + (b + 1) * width:.3g} {fu}")
        if law_v.size and law_v.size == law_0.size:
            mean = float(L[mine].mean())
            curve = law_0 + mu * mean * np.sign(law_v)
            for side in (law_v < 0, law_v > 0):  # no line through the jump at zero velocity
                a.plot(law_v[side], curve[side], "-", lw=2.2, color=colour,
                       label=f"law at |load| {mean:.3g} {fu}" if side[-1] else None)
    a.axhline(0, color="0.4", lw=0.8)
    a.axvline(0, color="0.4", lw=0.8)
    _friction_axes(a, fu, title or f"idim: friction against velocity and load, mu_load = {mu:.3g}")
    return _done(fig, [a], file, True)


def ripple(result, *, ax=None, file=None, title=None):
    """The position ripple of an idim result with the 'ripple' term: at each fitted sample the
    fit's residual plus the identified ripple, against the position within the ripple period, and
    the identified ripple over one period. Returns the Figure (or ``ax``). Raises ValueError on a
    result without the ripple term."""
    q, F, qc, Fc = _condition_series(
        result, ("ripple_position", "ripple_partial", "ripple_curve_position", "ripple_curve_force"), "ripple", "ripple")
    fu = _force_unit(result)
    pu = "rad" if fu == "N m" else "m"
    fig, (a,) = _axes(ax, 1, (9, 4.5))
    a.plot(q, F, ".", ms=2, color="0.6", label="samples: residual + identified ripple")
    a.plot(qc, Fc, "-", lw=2.2, color="#d55e00", label="identified ripple")
    a.axhline(0, color="0.4", lw=0.8)
    a.set_xlim(0, float(qc[-1]))
    a.set_xlabel(f"position within the ripple period ({pu})")
    a.set_ylabel(f"ripple force ({fu})")
    a.set_title(title or f"idim: position ripple over one period ({qc[-1]:.4g} {pu})")
    a.grid(True, alpha=0.3)
    _legend(a)
    return _done(fig, [a], file, True)


def temperature(result, *, ax=None, file=None, title=None):
    """The temperature drift of an idim result with the 'temperature' term: the logged temperature
    over time (top) and the viscous coefficient Fv + Fv_per_K (T - T_ref) it gives (bottom).
    ``ax``: two Axes. Returns the Figure (or the two Axes). Raises ValueError on a result without
    the temperature term."""
    t, T, fv = _condition_series(result, ("time", "temperature", "temperature_viscous"), "temperature", "temperature")
    unit_fv = result.parameters["Fv"].unit if "Fv" in result else "N s/m"
    ref = result.diagnostics.numbers.get("temperature_ref")
    fig, (a, b) = _axes(ax, 2, (9, 6))
    a.plot(t, T, "-", color="#d55e00", label="logged temperature")
    a.set_ylabel("temperature (degC or K, as logged)")
    a.set_title(title or "idim: temperature drift of the viscous coefficient")
    a.grid(True, alpha=0.3)
    _legend(a)
    b.plot(t, fv, "-", color="#0072b2",
           label="Fv + Fv_per_K (T - T_ref)" + (f", T_ref = {ref:.4g}" if ref is not None else ""))
    b.set_ylabel(f"viscous coefficient ({unit_fv})")
    b.set_xlabel("time (s)")
    b.grid(True, alpha=0.3)
    _legend(b)
    return _done(fig, [a, b], file, False)
