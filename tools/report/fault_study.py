#!/usr/bin/python3
"""GNSS fault study of paper scenario #2 (docs/fault-study.md): an outage that ends against the paper's permanent loss.

usage: /usr/bin/python3 tools/report/fault_study.py [--gdnav build/bin/gdnav] [--runs 100] [--jobs 2] [--seed S]
           [--out out/fault_study] [--figure docs/results/fault_study_s2_gnss_return.png] [--analyse-only]

Runs two `gdnav montecarlo` batches of scenario #2 in the direct layout, on the same seed and run indices (so run i
of both has the same mission, wind, offsets, sensor errors and turbulence):

  gnss_returns/  GNSS kept by the sensor (`never_lost`) and every GnssSample dropped from 100.5 s to 300 s (a `drop`
                 fault, framework/faults): the last fix before the outage is the 100 s one, as in the paper scenario,
                 and the fixes come back from 300 s. The runs are bit-identical to the paper runs until nav_pos
                 re-acquires (304 s).
  paper2/        the unfaulted paper scenario: GNSS lost for good at t_GNSS = 100 s.

Both batches are resumable (`gdnav montecarlo`); run the same command again to complete them. Then, from each
complete run's metrics.yaml, run.h5 (/error, /estimate) and log.txt (nav_pos's MODE messages), it writes:

  OUT/fault_study.md    the table: final horizontal error, max horizontal error during the outage [100, 300) s and
                        after the return [305, 500] s, the time to re-acquire after the first returned fix, the
                        attitude error (run mean and max of |dr|): mean / std / max over runs, per batch
  OUT/fault_study_runs.csv   the per-run figures
  FIGURE                horizontal error versus time: mean over runs and the 10-90 % band, both batches (linear and
                        logarithmic scales)

Needs Debian's python3-numpy, python3-h5py, python3-matplotlib and python3-yaml (call /usr/bin/python3).
"""
import argparse
import csv
import math
import os
import re
import statistics
import subprocess
import sys

import h5py
import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402
import yaml  # noqa: E402

DEG = 180.0 / math.pi
T_LOSS = 100.0      # paper t_GNSS: the last fix of both batches before the outage
T_RETURN = 300.0    # first fix after the outage (gnss_returns)
OUTAGE = "faults=[{at_s: 100.5, until_s: 300, target: sensors_gnss, kind: drop}]"
BATCHES = [
    ("gnss_returns", "GNSS returns at 300 s", ["components.sensors_gnss.never_lost=true", OUTAGE], "tab:blue"),
    ("paper2", "GNSS lost for good (paper)", [], "tab:red"),
]
REACQ = re.compile(r"\[nav_pos\] step \d+ t=([-0-9.]+) s: GNSS re-acquired")
LOST = re.compile(r"\[nav_pos\] step \d+ t=([-0-9.]+) s: GNSS lost")


def run_batch(args, name, sets):
    cmd = [args.gdnav, "montecarlo", "--scenario", "2", "--runs", str(args.runs), "--jobs", str(args.jobs),
           "--layout", "direct", "--no-report", "--out", os.path.join(args.out, name)]
    if args.seed is not None:
        cmd += ["--seed", str(args.seed)]
    for s in sets:
        cmd += ["--set", s]
    print("+", " ".join(f"'{c}'" if " " in c else c for c in cmd), flush=True)
    return subprocess.call(cmd)


def window(t, x, lo, hi):
    m = (t >= lo) & (t < hi)
    return x[m]


def analyse_run(run_dir):
    """Per-run figures, or None when the run is not complete."""
    mpath, hpath, lpath = (os.path.join(run_dir, f) for f in ("metrics.yaml", "run.h5", "log.txt"))
    if not (os.path.isfile(mpath) and os.path.isfile(hpath)):
        return None
    with open(mpath) as f:
        rec = yaml.safe_load(f)
    if rec.get("complete") is not True:
        return None
    with h5py.File(hpath, "r") as f:
        e = f["error"]
        t, hor, rot = e["t_s"][:], e["hor_m"][:], e["rot_rad"][:]
        denied_t, denied = f["estimate"]["t_s"][:], f["estimate"]["gnss_denied"][:]
    log = open(lpath, errors="replace").read() if os.path.isfile(lpath) else ""
    reacq = [float(x) for x in REACQ.findall(log)]
    lost = [float(x) for x in LOST.findall(log)]
    t_back = next((x for x in reacq if x >= T_RETURN), None)
    if t_back is None and not log:  # no log: the first 10 Hz row aided again after the return
        back = (denied_t >= T_RETURN) & (denied == 0)
        t_back = float(denied_t[back][0]) if back.any() else None
    sig = rec["signals"]
    return {
        "index": int(rec["run_index"]),
        "t": t,
        "hor": hor,
        "lost_s": lost[0] if lost else float("nan"),
        "reacquire_s": (t_back - T_RETURN) if t_back is not None else float("nan"),
        "hor_final_m": float(sig["hor_m"]["final"]),
        "hor_final_pct": float(rec["final_percent"]["hor"]),
        "hor_aided_mean_m": float(np.mean(window(t, hor, 0.0, T_LOSS))),
        "hor_outage_max_m": float(np.max(window(t, hor, T_LOSS, T_RETURN))),
        "hor_after_max_m": float(np.max(window(t, hor, T_RETURN + 5.0, 1e9))),
        "att_mean_deg": float(sig["rot_rad"]["mean"]) * DEG,
        "att_max_deg": abs(float(sig["rot_rad"]["max"])) * DEG,
        "att_max_after_return_deg": float(np.max(window(t, rot, T_RETURN, 1e9))) * DEG,
    }


def load_batch(path):
    root = os.path.join(path, "runs")
    out = []
    for name in sorted(os.listdir(root)) if os.path.isdir(root) else []:
        r = analyse_run(os.path.join(root, name))
        if r is not None:
            out.append(r)
    return out


ROWS = [  # key, label, format
    ("hor_final_m", "final horizontal error [m]", "{:.1f}"),
    ("hor_final_pct", "final horizontal error [% of distance since 100 s]", "{:.3f}"),
    ("hor_aided_mean_m", "horizontal error before the loss, run mean over [0, 100) s [m]", "{:.2f}"),
    ("hor_outage_max_m", "max horizontal error during the outage, [100, 300) s [m]", "{:.1f}"),
    ("hor_after_max_m", "max horizontal error after the return, [305, 500] s [m]", "{:.1f}"),
    ("reacquire_s", "time to re-acquire after the first returned fix (300 s) [s]", "{:.2f}"),
    ("att_mean_deg", "attitude error ‖Δr‖, run mean [deg]", "{:.3f}"),
    ("att_max_deg", "attitude error ‖Δr‖, run max [deg]", "{:.3f}"),
    ("att_max_after_return_deg", "attitude error ‖Δr‖, run max over [300, 500] s [deg]", "{:.3f}"),
]


def cell(runs, key, fmt):
    v = [r[key] for r in runs if math.isfinite(r[key])]
    if not v:
        return "— (never)" if key == "reacquire_s" else "—"
    s = " / ".join(fmt.format(x) for x in (statistics.fmean(v), statistics.pstdev(v), max(v)))
    return s if len(v) == len(runs) else f"{s} ({len(v)} of {len(runs)} runs)"


def table(batches):
    head = "| quantity (mean / std / max over runs) | " + " | ".join(f"{label} ({len(runs)} runs)"
                                                                     for _, label, runs, _ in batches) + " |"
    lines = [head, "|---|" + "--:|" * len(batches)]
    for key, label, fmt in ROWS:
        lines.append(f"| {label} | " + " | ".join(cell(runs, key, fmt) for _, _, runs, _ in batches) + " |")
    return "\n".join(lines)


def figure(path, batches):
    fig, axes = plt.subplots(2, 1, figsize=(9, 7.5), sharex=True)
    for _, label, runs, color in batches:
        if not runs:
            continue
        n = min(len(r["t"]) for r in runs)
        t = runs[0]["t"][:n]
        keep = t >= 0.0
        h = np.vstack([r["hor"][:n] for r in runs])[:, keep]
        t = t[keep]
        mean, lo, hi = h.mean(axis=0), np.percentile(h, 10, axis=0), np.percentile(h, 90, axis=0)
        for ax in axes:
            ax.fill_between(t, lo, hi, color=color, alpha=0.2, lw=0)
            ax.plot(t, mean, color=color, lw=1.4, label=f"{label}: mean over {len(runs)} runs")
            ax.plot([], [], color=color, alpha=0.35, lw=6, label=f"{label}: 10-90 % of runs")
    for ax in axes:
        for x, what in ((T_LOSS, "GNSS lost"), (T_RETURN, "GNSS returns")):
            ax.axvline(x, color="k", ls=":", lw=0.9)
            ax.text(x + 3, 0.97, what, transform=ax.get_xaxis_transform(), va="top", fontsize=8)
        ax.grid(True, which="both", alpha=0.3)
        ax.set_ylabel("horizontal error [m]")
    axes[1].set_yscale("log")
    axes[1].set_ylabel("horizontal error [m] (log)")
    axes[0].legend(loc="upper left", fontsize=8, bbox_to_anchor=(0.0, 0.9))
    axes[0].set_title("Scenario #2, direct layout: GNSS lost at 100 s; returns at 300 s (blue) or never (red)",
                      fontsize=10)
    axes[1].set_xlabel("t [s]")
    fig.tight_layout()
    fig.savefig(path, dpi=110)
    plt.close(fig)


def git_version():
    here = os.path.dirname(os.path.abspath(__file__))
    try:
        head = subprocess.check_output(["git", "-C", here, "rev-parse", "--short", "HEAD"], text=True).strip()
        dirty = subprocess.call(["git", "-C", here, "diff", "--quiet", "HEAD"]) != 0
        return head + (" (with uncommitted changes)" if dirty else "")
    except (OSError, subprocess.CalledProcessError):
        return "unknown"


def main():
    p = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    p.add_argument("--gdnav", default="build/bin/gdnav")
    p.add_argument("--runs", type=int, default=100)
    p.add_argument("--jobs", type=int, default=2)
    p.add_argument("--seed", type=int, default=None, help="master seed (default: the scenario file's)")
    p.add_argument("--out", default="out/fault_study")
    p.add_argument("--figure", default=None, help="PNG path (default OUT/fault_study_s2_gnss_return.png)")
    p.add_argument("--analyse-only", action="store_true", help="do not run the batches, only read them")
    args = p.parse_args()
    fig_path = args.figure or os.path.join(args.out, "fault_study_s2_gnss_return.png")

    failed = 0
    if not args.analyse_only:
        for name, _, sets, _ in BATCHES:
            failed |= run_batch(args, name, sets) != 0
    batches = [(name, label, load_batch(os.path.join(args.out, name)), color) for name, label, _, color in BATCHES]
    if not all(runs for _, _, runs, _ in batches):
        sys.exit("fault_study: a batch has no complete run")
    with open(os.path.join(args.out, "fault_study_runs.csv"), "w", newline="") as f:
        w = csv.writer(f)
        keys = ["index", "lost_s"] + [k for k, _, _ in ROWS]
        w.writerow(["batch"] + keys)
        for name, _, runs, _ in batches:
            for r in runs:
                w.writerow([name] + [r[k] for k in keys])
    text = table(batches)
    info = (f"gdnav {git_version()}; seed {args.seed if args.seed is not None else 'of paper2.yaml'}; "
            f"{len(batches[0][2])} and {len(batches[1][2])} complete runs; direct layout")
    with open(os.path.join(args.out, "fault_study.md"), "w") as f:
        f.write(f"<!-- {info} -->\n{text}\n")
    figure(fig_path, batches)
    print(info)
    print(text)
    print(f"figure: {fig_path}\ntable: {os.path.join(args.out, 'fault_study.md')}")
    sys.exit(1 if failed else 0)


if __name__ == "__main__":
    main()
