"""Figures with matplotlib, the same as the command line's --plot:

  sweep(result)        friction-velocity map: points with error bars and the fitted law
  idim(result)         measured vs reconstructed force (and the residual)
  simulation(traj)     time series of a simulation
  decay(t, x)          free decay with its peaks and the fitted envelope
  drift(table)         a fleet's parameters with their std against the log's date, flagged changes marked

Each returns the matplotlib Figure and, with ``file=``, writes it (PNG by the extension).
matplotlib is imported here only, so ``import frictionlab`` does not need it.
"""
import numpy as np

from .analysis import decay_envelope
from .methods.idim import idim_reconstruction

# Force unit -> velocity unit of the same axis, for labels.
_VELOCITY_UNIT = {"N": "m/s", "N m": "rad/s"}


def _figure(nrows=1, figsize=(7, 4.5), sharex=True):
    import matplotlib.pyplot as plt

    fig, axes = plt.subplots(nrows, 1, figsize=figsize, sharex=sharex, squeeze=False)
    return fig, list(axes[:, 0])


def _finish(fig, file, dpi=100):
    fig.tight_layout()
    if file is not None:
        fig.savefig(file, dpi=dpi)
    return fig


def _force_unit(result):
    units = result.units
    for name in ("Fc", "Fc_pos", "offset", "Fs"):
        if name in units:
            return units[name]
    return "N"


def sweep(result, *, file=None, title=None):
    """Friction-velocity map of a sweep result: segment means with ±1 std error bars, and the
    fitted law over the measured velocity range. Returns the Figure."""
    points = result.diagnostics.lists.get("points", [])
    if not points:
        raise ValueError("sweep plot: the result has no points (diagnostics.lists['points'])")
    v = np.array([p["velocity"] for p in points])
    f = np.array([p["force"] for p in points])
    fig, (ax,) = _figure()
    ax.errorbar(v, f, xerr=[p["velocity_std"] for p in points], yerr=[p["force_std"] for p in points], fmt="o",
                ms=4, capsize=3, label="steady segments")
    law = result.law
    if law is not None:
        lo, hi = min(v.min(), 0.0), max(v.max(), 0.0)
        grid = np.concatenate([np.linspace(lo, -1e-9 * (hi - lo), 300) if lo < 0 else [],
                               np.linspace(1e-9 * (hi - lo), hi, 300) if hi > 0 else []])
        ax.plot(grid, law.sliding(grid), "-", label=f"fitted {law.name}")
    fu = _force_unit(result)
    ax.set_xlabel(f"velocity ({_VELOCITY_UNIT.get(fu, 'm/s')})")
    ax.set_ylabel(f"friction ({fu})")
    ax.set_title(title or f"sweep: {result.model}, relative error {result.fit.relative_error_percent:.3g} %")
    ax.grid(True, alpha=0.3)
    ax.legend()
    return _finish(fig, file)


def idim(result, *, file=None, title=None):
    """Measured vs reconstructed force of an idim result (decimated samples), and the residual.
    Returns the Figure."""
    rec = idim_reconstruction(result)
    fu = _force_unit(result)
    fig, (ax, ax_res) = _figure(2, figsize=(8, 6))
    ax.plot(rec["time"], rec["measured"], "-", lw=1, label="measured")
    ax.plot(rec["time"], rec["reconstructed"], "--", lw=1, label="reconstructed")
    ax.set_ylabel(f"force ({fu})")
    ax.set_title(title or f"idim: {result.model}, relative error {result.fit.relative_error_percent:.3g} %")
    ax.legend()
    ax.grid(True, alpha=0.3)
    ax_res.plot(rec["time"], rec["residual"], "-", lw=0.8, color="tab:red")
    ax_res.set_ylabel(f"residual ({fu})")
    ax_res.set_xlabel("time (s)")
    ax_res.grid(True, alpha=0.3)
    return _finish(fig, file)


def simulation(trajectory, columns=("position", "velocity", "friction"), *, file=None, title=None):
    """Time series of a simulation (a Trajectory or a dict of columns), one panel per column.
    Returns the Figure."""
    columns = list(columns)
    fig, axes = _figure(len(columns), figsize=(8, 2.2 * len(columns) + 1))
    t = np.asarray(trajectory["time"])
    for ax, name in zip(axes, columns):
        ax.plot(t, np.asarray(trajectory[name]), lw=1)
        ax.set_ylabel(name)
        ax.grid(True, alpha=0.3)
    axes[-1].set_xlabel("time (s)")
    if title:
        axes[0].set_title(title)
    return _finish(fig, file)


def decay(t, x=None, *, envelope=None, file=None, title=None):
    """A free decay: position with its peaks (top), and the half-swing amplitudes with the
    fitted envelope of the detected kind (bottom). ``t`` and ``x`` (s; m or rad), or a
    Trajectory / dict as ``t``. ``envelope``: an EnvelopeResult (computed when not given).
    Returns the Figure."""
    if x is None:
        t, x = t["time"], t["position"]
    t, x = np.asarray(t, dtype=float), np.asarray(x, dtype=float)
    env = envelope if envelope is not None else decay_envelope(t, x)
    fig, (ax, ax_env) = _figure(2, figsize=(8, 6))
    ax.plot(t, x, lw=1, label="position")
    peaks = env.peak_times
    ax.plot(peaks, np.interp(peaks, t, x), "o", ms=4, label="extremes")
    ax.set_ylabel("position")
    ax.legend()
    ax.grid(True, alpha=0.3)
    ax.set_title(title or f"decay: {env.kind} ({len(env.amplitudes)} half cycles)")
    ax_env.plot(peaks, env.amplitudes, "o", ms=4, label="half-swing amplitude")
    grid = np.linspace(peaks.min(), peaks.max(), 300) if len(peaks) else peaks
    ax_env.plot(grid, env.envelope(grid), "-", label=f"{env.kind} envelope")
    ax_env.set_xlabel("time (s)")
    ax_env.set_ylabel("amplitude")
    ax_env.legend()
    ax_env.grid(True, alpha=0.3)
    return _finish(fig, file)


def drift(table, parameters=None, *, file=None, title=None):
    """A fleet's drift: one panel per parameter, its value with ±1 std error bars against the
    log's date, the changes the drift rule flagged (frictionlab.batch.drift) circled in red.
    ``table``: a drift Table (batch.drift) or an identification Table with dates (drift is
    computed with the default threshold). ``parameters``: names to draw (default all).
    Returns the Figure."""
    import datetime

    from .batch import drift as drift_table

    if getattr(table, "kind", "drift") != "drift":
        table = drift_table(table)
    rows = list(table)
    if not rows:
        raise ValueError("drift plot: the table has no rows (no ok identification with a date)")
    names = list(parameters) if parameters else list(dict.fromkeys(r["parameter"] for r in rows))
    fig, axes = _figure(len(names), figsize=(8, 2.2 * len(names) + 1))
    for ax, name in zip(axes, names):
        mine = [r for r in rows if r["parameter"] == name]
        if not mine:
            raise ValueError(f"drift plot: no parameter '{name}' in the table")
        dates = [datetime.datetime.fromisoformat(r["date"]) for r in mine]
        values = np.array([r["value"] for r in mine], dtype=float)
        stds = np.array([np.nan if r["std"] is None else r["std"] for r in mine], dtype=float)
        ax.errorbar(dates, values, yerr=np.nan_to_num(stds), fmt="o-", ms=4, capsize=3, lw=1)
        flagged = [k for k, r in enumerate(mine) if r["flagged"]]
        if flagged:
            ax.plot([dates[k] for k in flagged], values[flagged], "o", ms=11, mfc="none", mec="tab:red", mew=1.5,
                    label="change > threshold x combined std")
            ax.legend(loc="best")
        unit = mine[0]["unit"]
        ax.set_ylabel(f"{name} ({unit})" if unit else name)
        ax.grid(True, alpha=0.3)
    axes[-1].set_xlabel("log date (UTC)")
    fig.autofmt_xdate()
    axes[0].set_title(title or f"drift over {len({r['file'] for r in rows})} logs")
    return _finish(fig, file)
