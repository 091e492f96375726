#!/usr/bin/python3
"""Comparison table of several gdnav Monte Carlo batches (one row per batch), as in docs/results.md.

usage: /usr/bin/python3 tools/report/compare.py LABEL=BATCH_DIR [LABEL=BATCH_DIR ...]

Reads BATCH_DIR/runs/run_*/metrics.yaml (complete runs only) and prints a markdown table: runs; mean over runs of
the per-run mean and of the per-run max of the attitude error angle; population std over runs of the final altitude
and north ground-speed errors; mean over runs of the final horizontal error [m], [%] and the std of [%]; and the
mean over runs of the attitude drift (least-squares slope after 500 s, metrics.yaml `trends`) when present.
Needs Debian's python3-yaml (call /usr/bin/python3).
"""
import math
import os
import statistics
import sys

import yaml

DEG = 180.0 / math.pi


def records(batch):
    root = os.path.join(batch, "runs")
    out = []
    for name in sorted(os.listdir(root)) if os.path.isdir(root) else []:
        path = os.path.join(root, name, "metrics.yaml")
        if os.path.isfile(path):
            with open(path) as f:
                rec = yaml.safe_load(f)
            if rec.get("complete") is True:
                out.append(rec)
    return out


def num(v):
    return float(v) if v is not None else float("nan")


def row(label, recs):
    sig = lambda r, k, s: num(r["signals"][k][s])  # noqa: E731
    att_mean = statistics.fmean(sig(r, "rot_rad", "mean") * DEG for r in recs)
    att_max = statistics.fmean(abs(sig(r, "rot_rad", "max")) * DEG for r in recs)
    h_std = statistics.pstdev(sig(r, "h_m", "final") for r in recs)
    vn_std = statistics.pstdev(sig(r, "vn_mps", "final") for r in recs)
    hor_m = statistics.fmean(sig(r, "hor_m", "final") for r in recs)
    pct = [num(r["final_percent"]["hor"]) for r in recs]
    drifts = [num(r["trends"]["att_slope_rad_per_s"]) * DEG * 1000.0 for r in recs if "trends" in r]
    drift = f"{statistics.fmean(drifts):+.4f}" if drifts else "n/a"
    return (f"| {label} | {len(recs)} | {att_mean:.3f} | {att_max:.3f} | {h_std:.2f} | {vn_std:.2f} | {hor_m:.0f} | "
            f"{statistics.fmean(pct):.2f} | {statistics.pstdev(pct):.2f} | {drift} |")


def main():
    if len(sys.argv) < 2 or any("=" not in a for a in sys.argv[1:]):
        sys.exit(__doc__)
    print("| configuration | runs | ‖Δr‖ mean of run means [deg] | ‖Δr‖ mean of run max [deg] | ĥ−h final std [m] "
          "| v̂_N−v_N final std [m/s] | Δx_hor final mean [m] | [%] | [%] std | ‖Δr‖ drift after 500 s, mean "
          "[deg/1000 s] |")
    print("|---|--:|--:|--:|--:|--:|--:|--:|--:|--:|")
    for arg in sys.argv[1:]:
        label, batch = arg.split("=", 1)
        recs = records(batch)
        if not recs:
            sys.exit(f"compare.py: no complete run in {batch}")
        print(row(label, recs))


if __name__ == "__main__":
    main()
