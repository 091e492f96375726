#!/usr/bin/python3
"""The whole-run attitude bound: how small could the attitude error of an ideal filter with this run's sensors be,
before and after the GNSS loss? (docs/navigation.md, "The ideal filter's bounds".)

  tools/report/attitude_bound.py [--run RUN_DIR ...] [--batch LABEL=DIR ...] [--runs N] [--png FILE]
                                 [--magnetometer vector|compass|none] [--no-air-data] [--config-dir DIR]

On the true trajectory of a run (RUN_DIR/run.h5 /truth at the recorder's rate, 10 Hz by default; a faster record is
thinned to about 10 Hz) it runs the covariance of an ideal linear Kalman filter with the run's sensors, from the
run's t0 to its end: the model, every simplification and which way it moves the bound are in
attitude_bound_model.py's docstring, the figures it takes from config/ and the numbers it derives in
attitude_bound_inputs.py's. It gives, per run:
  * the heading sigma at the GNSS loss (the body attitude error about the down axis) and the tilt sigma (about N, E);
  * the expected attitude error norm E||dr|| averaged over the window of the metric ||dr_hat|| (nav_recorder: t in
    [metrics_start_s (0), t_end_s of metrics.yaml], docs/montecarlo.md), and over the denied phase (t_GNSS, t_end]
    alone (E||x|| of the 3-D Gaussian, not sqrt(trace P): see the model's docstring).
--run: the bound and, beside it, the run's own filter (metrics.yaml signals.rot_rad.mean, the mean of ||dr_hat|| over
the same window; |psi_hat - psi| at the loss from run.h5 /error). --batch LABEL=DIR (several): the bound on the truth
of each complete run of the batch (the first N with --runs; one progress line per run on stderr; runs whose mean
attitude error is above 20 deg left out as diverged, as heading_bound.py does) and, per batch over the same runs, the
mean of the per-run mean ||dr_hat|| against the mean of the per-run bound, and the rms heading error at the loss
against the rms of the bound's heading sigma, each with "x % above the bound". --png: the bound's tilt and heading
sigma against time (top), and the rms attitude error against time of the bound (sqrt(E||dr||^2) = sqrt(trace P))
and of the filters (run.h5 /error rot_rad, rms over the batch's runs) (bottom), the GNSS loss marked.
--magnetometer compass: heading_bound.py's compass instead of the vector magnetometer; none: no magnetometer.
--no-air-data: no air data. Bad input is one line (attitude_bound: ...) and exit code 2.
Debian's python3-h5py, -numpy, -yaml, -matplotlib.
"""
import argparse
import math
import os
import sys

import numpy as np

import attitude_bound_inputs as ai
import attitude_bound_model as am
import heading_bound as hb
from heading_bound import DEG, InputError

DIVERGED_DEG = 20.0  # heading_bound.py's rule for a run that lost the attitude


def above(value, bound):
    return 100.0 * (value / bound - 1.0) if bound > 0 and math.isfinite(value) else math.nan


def fmt_pct(x):
    return "n/a" if not math.isfinite(x) else f"{x:+.0f} %"


def fmt_deg(x_rad, digits=3):
    return "n/a" if not math.isfinite(x_rad) else f"{x_rad * DEG:.{digits}f}°"


def batch_results(label, batch, config_dir, n_runs, magnetometer, air_data):
    runs = hb.complete_runs(batch)
    if n_runs is not None:
        runs = runs[:n_runs]
    if not runs:
        raise InputError(f"'{batch}' has no complete run with run.h5")
    kept, n_div = [], 0
    for i, (run, m) in enumerate(runs):
        try:
            lost = hb.diverged(m, DIVERGED_DEG)
        except (KeyError, TypeError):
            raise InputError(f"'{run}/metrics.yaml' has no signals.rot_rad mean (a run without a reference "
                             f"trajectory?)") from None
        if lost:
            n_div += 1
            print(f"attitude_bound: {label} {i + 1}/{len(runs)} {os.path.basename(run)}: diverged, left out",
                  file=sys.stderr)
            continue
        inp = ai.run_inputs(run, config_dir)
        b = am.run_bound(inp, magnetometer, air_data)
        rot, head = ai.filter_figures(inp)
        print(f"attitude_bound: {label} {i + 1}/{len(runs)} {os.path.basename(run)}: "
              f"bound {fmt_deg(b['mean_window_rad'])}, "
              f"filter {fmt_deg(rot)}", file=sys.stderr)
        err = inp["error"]
        kept.append({"bound": b, "rot_rad": rot, "heading_error_rad": head,
                     "err_t_s": err["t_s"] if err is not None else None,
                     "err_rot_rad": err["rot_rad"] if err is not None and "rot_rad" in err.dtype.names else None})
    if not kept:
        raise InputError(f"'{batch}': every run of the first {len(runs)} diverged")
    return {"label": label, "runs": kept, "diverged": n_div}


def common_grid(series):
    """A 0.1 s grid over the span every (t, ...) series covers."""
    t0 = max(t[0] for t in series)
    t1 = min(t[-1] for t in series)
    if t1 < t0:
        raise InputError("the runs of a batch share no time span (not one scenario?)")
    return np.arange(math.ceil(t0 * 10.0 - 1e-6), math.floor(t1 * 10.0 + 1e-6) + 1) / 10.0


def batch_curves(res):
    """rms over the batch's runs, on a common grid, of the bound's tilt, heading and rms, and of the filters'
    ||dr_hat||."""
    ts = [r["bound"]["t_s"] for r in res["runs"]]
    grid = common_grid(ts)

    def rms(key):
        return np.sqrt(np.mean([np.interp(grid, r["bound"]["t_s"], r["bound"][key] ** 2) for r in res["runs"]], axis=0))

    tilt = np.sqrt(0.5 * (rms("tilt_n_rad") ** 2 + rms("tilt_e_rad") ** 2))
    out = {"t_s": grid, "tilt_rad": tilt, "heading_rad": rms("heading_rad"), "rms_rad": rms("rms_rad"),
           "filter_rad": None}
    with_err = [r for r in res["runs"] if r["err_rot_rad"] is not None]
    if with_err:
        g = common_grid([r["err_t_s"] for r in with_err])
        out["filter_t_s"] = g
        out["filter_rad"] = np.sqrt(np.nanmean([np.interp(g, r["err_t_s"], r["err_rot_rad"] ** 2) for r in with_err],
                                               axis=0))
    return out


def figure(path, singles, batches):
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    fig, (ax1, ax2) = plt.subplots(2, 1, figsize=(12, 7.5), sharex=True)
    colours = plt.rcParams["axes.prop_cycle"].by_key()["color"]
    losses = set()
    curves = []
    for name, b, inp in singles:
        rot_t = inp["error"]["t_s"] if inp["error"] is not None else None
        rot = inp["error"]["rot_rad"] if inp["error"] is not None else None
        tilt = np.sqrt(0.5 * (b["tilt_n_rad"] ** 2 + b["tilt_e_rad"] ** 2))
        curves.append((name, b["t_s"], tilt, b["heading_rad"], b["rms_rad"], rot_t,
                       np.abs(rot) if rot is not None else None, "filter |Δr̂|"))
        losses.add(b["t_gnss_s"])
    for res in batches:
        c = batch_curves(res)
        curves.append((f"{res['label']} ({len(res['runs'])} runs)", c["t_s"], c["tilt_rad"], c["heading_rad"],
                       c["rms_rad"], c.get("filter_t_s"), c["filter_rad"], "filters' rms ‖Δr̂‖"))
        losses.update(r["bound"]["t_gnss_s"] for r in res["runs"])
    floor = min(float(np.min(c[4])) for c in curves)
    for i, (name, t, tilt, head, rms, ft, fr, what) in enumerate(curves):
        col = colours[i % len(colours)]
        ax1.semilogy(t, tilt * DEG, color=col, lw=1.2, label=f"{name}: bound tilt σ (rms of N, E)")
        ax1.semilogy(t, head * DEG, color=col, lw=1.2, ls="--", label=f"{name}: bound heading σ")
        ax2.semilogy(t, rms * DEG, color=col, lw=1.5, ls="--", label=f"{name}: bound rms ‖Δr‖ = √trace P")
        if fr is not None:
            ax2.semilogy(ft, np.maximum(fr * DEG, 1e-4), color=col, lw=0.8, alpha=0.8, label=f"{name}: {what}")
    # A single run's error dips towards zero at its sign changes: the axis starts a decade below the bound.
    ax2.set_ylim(bottom=0.1 * floor * DEG)
    for ax in (ax1, ax2):
        for tl in sorted(losses):
            ax.axvline(tl, color="k", lw=0.8, ls=":")
        ax.grid(True, which="both", alpha=0.3)
        ax.legend(fontsize=8, loc="upper left", bbox_to_anchor=(1.01, 1.0), borderaxespad=0.0)
    ax1.set_ylabel("1σ [deg]")
    ax1.set_title("Ideal filter on the run's true trajectory and sensors (GNSS lost at the dotted line)")
    ax2.set_ylabel("attitude error [deg]")
    ax2.set_xlabel("t [s]")
    ax2.set_title("rms attitude error: the bound (dashed) and the filters (solid)")
    fig.tight_layout()
    fig.savefig(path, dpi=110)
    plt.close(fig)


class Parser(argparse.ArgumentParser):
    """Option errors as InputError: one line, like every other bad input."""

    def error(self, message):
        raise InputError(message)


def run_main(argv):
    ap = Parser(description=__doc__.split("\n")[0])
    ap.add_argument("--run", action="append", default=[], help="run folder: the bound on its truth, and its filter")
    ap.add_argument("--batch", action="append", default=[], help="LABEL=DIR: a montecarlo batch, the bound per run")
    ap.add_argument("--runs", type=int, help="only the first N complete runs of each batch (default: all)")
    ap.add_argument("--magnetometer", choices=("vector", "compass", "none"), default="vector")
    ap.add_argument("--no-air-data", action="store_true", help="leave the air data out (before and after the loss)")
    ap.add_argument("--config-dir", default=os.path.join(os.path.dirname(os.path.abspath(__file__)), "../../config"))
    ap.add_argument("--png", help="figure of the bound (and the filters) against time")
    a = ap.parse_args(argv)
    if not a.run and not a.batch:
        raise InputError("give at least one --run RUN_DIR or --batch LABEL=DIR")
    if a.runs is not None and a.runs < 1:
        raise InputError(f"--runs must be at least 1, got {a.runs}")
    batches = []
    for b in a.batch:
        if "=" not in b or not b.split("=", 1)[0] or not b.split("=", 1)[1]:
            raise InputError(f"--batch takes LABEL=DIR, got '{b}'")
        batches.append(tuple(b.split("=", 1)))
    if a.png and not os.path.isdir(os.path.dirname(os.path.abspath(a.png))):
        raise InputError(f"the folder of --png '{a.png}' does not exist")
    air = not a.no_air_data
    model = f"magnetometer {a.magnetometer}, air data {'on' if air else 'off'}"
    singles = []
    for run in a.run:
        inp = ai.run_inputs(run, a.config_dir)
        b = am.run_bound(inp, a.magnetometer, air)
        rot, head = ai.filter_figures(inp)
        s = b["figures"]
        singles.append((os.path.basename(os.path.normpath(run)), b, inp))
        w0, w1 = b["window_s"]
        turb = ", ".join(f"{x:.2f}" for x in s["turb_sigma_mps"])
        print(f"{run}: start '{s['init_mode']}' at t0 = {b['t_s'][0]:g} s, GNSS lost at {b['t_gnss_s']:g} s ({model}; "
              f"turbulence {turb} m/s, {s['turb_tau_s']:.1f} s)")
        print(f"  bound: heading σ at the loss {fmt_deg(b['heading_at_loss_rad'])}, "
              f"tilt σ {fmt_deg(b['tilt_at_loss_rad'])}; E‖Δr‖ mean over [{w0:g}, {w1:g}] s "
              f"{fmt_deg(b['mean_window_rad'])}, after the loss {fmt_deg(b['mean_after_rad'])}")
        print(f"  filter: mean ‖Δr̂‖ {fmt_deg(rot)} ({fmt_pct(above(rot, b['mean_window_rad']))} above the bound), "
              f"|heading error| at the loss {fmt_deg(head)} "
              f"({fmt_pct(above(head, b['heading_at_loss_rad']))})")
    results = [batch_results(label, d, a.config_dir, a.runs, a.magnetometer, air) for label, d in batches]
    if results:
        print(f"| batch ({model}) | runs (diverged, left out) | mean ‖Δr̂‖ | bound E‖Δr‖ | above | "
              f"rms heading error at the loss | bound heading σ | above |")
        print("|---|--:|--:|--:|--:|--:|--:|--:|")
        for res in results:
            rot = float(np.nanmean([r["rot_rad"] for r in res["runs"]]))
            bound = float(np.mean([r["bound"]["mean_window_rad"] for r in res["runs"]]))
            head = float(np.sqrt(np.nanmean([r["heading_error_rad"] ** 2 for r in res["runs"]])))
            hbound = float(np.sqrt(np.mean([r["bound"]["heading_at_loss_rad"] ** 2 for r in res["runs"]])))
            print(f"| {res['label']} | {len(res['runs'])} ({res['diverged']}) | {fmt_deg(rot)} | {fmt_deg(bound)} | "
                  f"{fmt_pct(above(rot, bound))} | {fmt_deg(head)} | {fmt_deg(hbound)} | "
                  f"{fmt_pct(above(head, hbound))} |")
    if a.png:
        figure(a.png, singles, results)
        print(f"figure: {a.png}")
    return 0


def main(argv=None):
    try:
        return run_main(argv)
    except InputError as e:
        print(f"attitude_bound: {e}", file=sys.stderr)
        return 2
    except OSError as e:
        print(f"attitude_bound: {e.filename or ''}: {e.strerror or e}", file=sys.stderr)
        return 2


if __name__ == "__main__":
    sys.exit(main())
