#!/usr/bin/python3
"""Figures of a gdnav Monte Carlo batch, like the paper's NSE figures.

usage: /usr/bin/python3 tools/report/report.py BATCH_DIR [--out DIR]

Reads BATCH_DIR/runs/run_*/metrics.yaml (complete runs only; failed runs, with a failure.yaml, are named on stderr)
and their run.h5 (/error table, docs/montecarlo.md),
and writes PNG figures to DIR (default BATCH_DIR/report):

  attitude_nse.png        yaw, pitch, bank errors and |dr|: across-run mean +- std versus time, best and worst run
                          (ranked by the per-run mean of |dr|)
  altitude_nse.png        geometric altitude error, best and worst run by |final error|
  ground_speed_nse.png    north and east ground speed errors, best and worst run by |final error|
  horizontal_nse.png      horizontal position error, best and worst run by final error
  air_data_nse.png        TAS, AOA, AOS and temperature offset errors
  attitude_scatter.png    per-run mean versus std of |dr| and of the Euler angle errors
  horizontal_final.png    per-run final cross- and along-track errors, and final error versus distance

Needs Debian's python3-numpy, python3-h5py and python3-matplotlib (call /usr/bin/python3, not a pyenv python).
The across-run statistics are streamed (one run in memory at a time), so 100 runs of scenario #1 fit easily.
"""
import argparse
import math
import os
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402

from batch_runs import (DEG, DamagedRun, Streamed, batch_label, final_distance, load_failures, load_runs, read_table,  # noqa: E402
                        signal)
from file_errors import naming  # noqa: E402

# (column of /error, label, scale to plot units, unit)
ATTITUDE = [("yaw_rad", r"$\hat\psi-\psi$", DEG, "deg"), ("pitch_rad", r"$\hat\theta-\theta$", DEG, "deg"),
            ("bank_rad", r"$\hat\xi-\xi$", DEG, "deg"), ("rot_rad", r"$\|\Delta\hat r\|$", DEG, "deg")]
AIR = [("tas_mps", r"$\hat v_{TAS}-v_{TAS}$", 1.0, "m/s"), ("aoa_rad", r"$\hat\alpha-\alpha$", DEG, "deg"),
       ("aos_rad", r"$\hat\beta-\beta$", DEG, "deg"), ("dT_K", r"$\Delta\hat T-\Delta T$", 1.0, "K")]
COLUMNS = [c[0] for c in ATTITUDE + AIR] + ["h_m", "vn_mps", "ve_mps", "hor_m", "cross_m", "along_m"]


def save(fig, path):
    """Writes FIG to PATH as PNG and closes it; a refused write names PATH (file_errors.naming)."""
    with naming(path):
        fig.savefig(path, dpi=110)
    plt.close(fig)


def read_error(path):
    return read_table(path, "error", COLUMNS)


def band(ax, t, mean, std, scale, label):
    ax.fill_between(t, (mean - std) * scale, (mean + std) * scale, color="tab:blue", alpha=0.25, lw=0,
                    label=r"mean $\pm$ std")
    ax.plot(t, mean * scale, color="tab:blue", lw=1.2, label="mean")
    ax.set_ylabel(label)
    ax.grid(True, alpha=0.3)


def extremes(ax, series, col, scale, best, worst):
    for run, color, what in ((best, "tab:green", "best"), (worst, "tab:red", "worst")):
        if run is None or run["index"] not in series:
            continue
        t, err = series[run["index"]]
        ax.plot(t, err[col] * scale, color=color, lw=0.7, alpha=0.9, label=f"{what} (run {run['index']})")


def time_figure(path, title, rows, stats, series, best, worst, t_gnss, t_min, ranking=""):
    fig, axes = plt.subplots(len(rows), 1, figsize=(9, 2.3 * len(rows) + 0.8), sharex=True, squeeze=False)
    keep = stats.t >= t_min
    for ax, (col, label, scale, unit) in zip(axes[:, 0], rows):
        mean, std = stats.mean_std(col)
        band(ax, stats.t[keep], mean[keep], std[keep], scale, f"{label} [{unit}]")
        extremes(ax, {k: (t[t >= t_min], {c: v[t >= t_min] for c, v in e.items()}) for k, (t, e) in series.items()},
                 col, scale, best, worst)
        ax.axvline(t_gnss, color="k", ls=":", lw=0.8)
    axes[0, 0].set_title(title + (f"\nbest / worst run: {ranking}" if ranking and best else ""), fontsize=10)
    axes[0, 0].legend(loc="upper left", fontsize=7, ncol=4)
    axes[-1, 0].set_xlabel("t [s]   (dotted: GNSS lost)")
    fig.tight_layout()
    save(fig, path)


def rank(runs, key, stat, absolute=True):
    vals = []
    for r in runs:
        v = signal(r["metrics"], key, stat)
        if math.isfinite(v):
            vals.append((abs(v) if absolute else v, r))
    if not vals:
        return None, None
    vals.sort(key=lambda x: (x[0], x[1]["index"]))
    return vals[0][1], vals[-1][1]


def scatter_figures(out, runs, label):
    fig, axes = plt.subplots(1, 2, figsize=(10, 4.2))
    m = np.array([signal(r["metrics"], "rot_rad", "mean") for r in runs]) * DEG
    s = np.array([signal(r["metrics"], "rot_rad", "std") for r in runs]) * DEG
    axes[0].scatter(m, s, s=14, color="tab:blue")
    axes[0].set_xlabel(r"run mean of $\|\Delta\hat r\|$ [deg]")
    axes[0].set_ylabel(r"run std of $\|\Delta\hat r\|$ [deg]")
    axes[0].set_title(f"Body attitude error per run ({label}, {len(runs)} runs)")
    for col, lab, _, _ in ATTITUDE[:3]:
        axes[1].scatter([signal(r["metrics"], col, "mean") * DEG for r in runs],
                        [signal(r["metrics"], col, "std") * DEG for r in runs], s=12, label=lab)
    axes[1].axvline(0.0, color="k", lw=0.6)
    axes[1].set_xlabel("run mean [deg]")
    axes[1].set_ylabel("run std [deg]")
    axes[1].set_title("Euler angle errors per run")
    axes[1].legend(fontsize=8)
    for ax in axes:
        ax.grid(True, alpha=0.3)
    fig.tight_layout()
    save(fig, os.path.join(out, "attitude_scatter.png"))

    fig, axes = plt.subplots(1, 2, figsize=(10, 4.2))
    cross = [signal(r["metrics"], "cross_m", "final") for r in runs]
    along = [signal(r["metrics"], "along_m", "final") for r in runs]
    axes[0].scatter(cross, along, s=14, color="tab:purple")
    axes[0].axhline(0.0, color="k", lw=0.6)
    axes[0].axvline(0.0, color="k", lw=0.6)
    axes[0].set_xlabel(r"final cross-track error [m] (> 0: right of track)")
    axes[0].set_ylabel(r"final along-track error [m] (> 0: ahead)")
    axes[0].set_title(f"Final horizontal error ({label})")
    lim = max([abs(v) for v in cross + along if math.isfinite(v)] + [1e-9]) * 1.15
    axes[0].set_xlim(-lim, lim)
    axes[0].set_ylim(-lim, lim)
    axes[0].set_aspect("equal")
    dist = np.array([final_distance(r["metrics"]) for r in runs]) / 1000.0  # up to t_end
    hor = [signal(r["metrics"], "hor_m", "final") for r in runs]
    axes[1].scatter(dist, hor, s=14, color="tab:orange")
    if len(dist) and np.nanmax(dist) > 0:
        x = np.linspace(0.0, np.nanmax(dist) * 1.05, 10)
        for pct in (1, 5, 10):
            axes[1].plot(x, x * 1000.0 * pct / 100.0, "k:", lw=0.7)
            axes[1].annotate(f"{pct} %", (x[-1], x[-1] * 10.0 * pct), fontsize=7)
        finite = [v for v in hor if math.isfinite(v)]
        if finite:
            axes[1].set_ylim(0.0, max(finite) * 1.3 + 1e-9)
    axes[1].set_xlabel(r"distance flown since $t_{GNSS}$ [km]")
    axes[1].set_ylabel(r"final $\Delta x_{hor}$ [m]")
    axes[1].set_title("Final horizontal error versus distance")
    for ax in axes:
        ax.grid(True, alpha=0.3)
    fig.tight_layout()
    save(fig, os.path.join(out, "horizontal_final.png"))


def main():
    p = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    p.add_argument("batch")
    p.add_argument("--out", default=None)
    a = p.parse_args()
    out = a.out or os.path.join(a.batch, "report")
    os.makedirs(out, exist_ok=True)
    try:
        runs = load_runs(a.batch)
    except DamagedRun as e:
        print(f"report.py: {e}", file=sys.stderr)
        return 1
    for f in load_failures(a.batch):  # left out of the figures; gdnav report lists them with their last log lines
        print(f"report.py: run {f['run']} failed (exit code {f.get('exit_code')}): {f.get('cause', '')}", file=sys.stderr)
    if not runs:
        print(f"report.py: no complete run in {a.batch}/runs", file=sys.stderr)
        return 1
    label = batch_label(a.batch)

    best_att, worst_att = rank(runs, "rot_rad", "mean")
    best_h, worst_h = rank(runs, "h_m", "final")
    best_vn, worst_vn = rank(runs, "vn_mps", "final")
    best_hor, worst_hor = rank(runs, "hor_m", "final")
    wanted = {r["index"] for r in (best_att, worst_att, best_h, worst_h, best_vn, worst_vn, best_hor, worst_hor) if r}
    stats, series, t_gnss = Streamed(COLUMNS), {}, 100.0
    for r in runs:
        t, err, t_gnss = read_error(r["h5"])
        stats.add(t, err)
        if r["index"] in wanted:
            series[r["index"]] = (t, err)
    n = f"{label}, {len(runs)} runs"
    t_min = 0.0
    time_figure(os.path.join(out, "attitude_nse.png"), f"Body attitude NSE ({n})", ATTITUDE, stats, series,
                best_att, worst_att, t_gnss, t_min, r"lowest / highest run mean of $\|\Delta\hat r\|$")
    time_figure(os.path.join(out, "altitude_nse.png"), f"Vertical position NSE ({n})",
                [("h_m", r"$\hat h-h$", 1.0, "m")], stats, series, best_h, worst_h, t_gnss, t_min,
                r"lowest / highest $|\hat h-h|$ at $t_{end}$")
    time_figure(os.path.join(out, "ground_speed_nse.png"), f"Ground speed NSE ({n})",
                [("vn_mps", r"$\hat v_N-v_N$", 1.0, "m/s"), ("ve_mps", r"$\hat v_E-v_E$", 1.0, "m/s")], stats,
                series, best_vn, worst_vn, t_gnss, t_min, r"lowest / highest $|\hat v_N-v_N|$ at $t_{end}$")
    time_figure(os.path.join(out, "horizontal_nse.png"), f"Horizontal position NSE ({n})",
                [("hor_m", r"$\Delta\hat x_{hor}$", 1.0, "m"), ("cross_m", r"$\Delta\hat x_{cross}$", 1.0, "m"),
                 ("along_m", r"$\Delta\hat x_{along}$", 1.0, "m")], stats, series, best_hor, worst_hor, t_gnss, t_min,
                r"lowest / highest $\Delta\hat x_{hor}$ at $t_{end}$")
    time_figure(os.path.join(out, "air_data_nse.png"), f"Air data NSE ({n})", AIR, stats, series, None, None,
                t_gnss, t_min)
    scatter_figures(out, runs, label)
    print(f"report.py: {len(runs)} runs -> figures in {out}")
    return 0


def main_one_line():
    """main(), with a file the operating system refused (a full disk) as one line and exit code 6, as gdnav's own
    writers (docs/runtime.md, "Exit codes")."""
    try:
        return main()
    except OSError as e:
        print(f"report.py: {e.filename}: {e.strerror}" if e.filename else f"report.py: {e}",
              file=sys.stderr)
        return 6


if __name__ == "__main__":
    sys.exit(main_one_line())
