#!/usr/bin/python3
"""In-flight alignment batches (docs/navigation.md "In-flight alignment", docs/results.md): truth-free starts against
the aligned start on the same runs of a calibrated scenario.

  tools/report/in_flight_alignment.py --aligned DIR --truth-free LABEL=DIR [--truth-free LABEL=DIR ...]
                                      [--diverged-deg 20] [--png FILE]

Prints, per truth-free batch, a Markdown row: runs paired with the aligned batch, runs diverged (mean attitude error
above --diverged-deg), the largest mean and largest maximum attitude error, mean attitude error and final horizontal
error (m and %) over the runs that did not diverge and of the aligned start on the same runs, the runs declared
aligned and the time to align (median and quartiles, from t0). With --png: per run, the truth-free mean attitude
error against the aligned one (log axes, one marker per batch), and the distribution of the time to align.
Debian's python3-yaml, -numpy, -matplotlib.
"""
import argparse
import math
import os
import sys

import numpy as np
import yaml

DEG = 180.0 / math.pi


def load(batch):
    """{run index: metrics.yaml} of the complete runs of BATCH/runs/run_*."""
    out = {}
    root = os.path.join(batch, "runs")
    if not os.path.isdir(root):
        sys.exit(f"in_flight_alignment: '{batch}' has no runs/ folder (not a gdnav montecarlo batch)")
    for name in sorted(os.listdir(root)):
        f = os.path.join(root, name, "metrics.yaml")
        if not os.path.isfile(f):
            continue
        with open(f) as fh:
            m = yaml.safe_load(fh)
        if m.get("complete") is True:
            out[int(m["run_index"])] = m
    if not out:
        sys.exit(f"in_flight_alignment: '{batch}' has no complete run")
    return out


def att_mean_deg(m):
    return m["signals"]["rot_rad"]["mean"] * DEG


def att_max_deg(m):
    return abs(m["signals"]["rot_rad"]["max"]) * DEG


def row(label, tf, al, diverged_deg):
    runs = sorted(set(tf) & set(al))
    div = [k for k in runs if att_mean_deg(tf[k]) > diverged_deg]
    ok = [k for k in runs if k not in div]
    t_align = [tf[k]["alignment"]["time_to_align_s"] for k in runs
               if tf[k].get("alignment", {}).get("aligned")]
    q = np.percentile(t_align, [25, 50, 75]) if t_align else [float("nan")] * 3

    def mean(f, ks):
        return float(np.mean([f(k) for k in ks])) if ks else float("nan")

    return {
        "label": label, "runs": len(runs), "diverged": len(div),
        "worst_mean": max(att_mean_deg(tf[k]) for k in runs), "worst_max": max(att_max_deg(tf[k]) for k in runs),
        "att_ok": mean(lambda k: att_mean_deg(tf[k]), ok), "att_al": mean(lambda k: att_mean_deg(al[k]), ok),
        "hor_ok": mean(lambda k: tf[k]["signals"]["hor_m"]["final"], ok),
        "hor_al": mean(lambda k: al[k]["signals"]["hor_m"]["final"], ok),
        "pct_ok": mean(lambda k: tf[k]["final_percent"]["hor"], ok),
        "pct_al": mean(lambda k: al[k]["final_percent"]["hor"], ok),
        "aligned": len(t_align), "t_q": q, "t_align": t_align,
        "pairs": [(att_mean_deg(al[k]), att_mean_deg(tf[k])) for k in runs],
    }


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    ap.add_argument("--aligned", required=True)
    ap.add_argument("--truth-free", action="append", required=True, metavar="LABEL=DIR")
    ap.add_argument("--diverged-deg", type=float, default=20.0)
    ap.add_argument("--png")
    a = ap.parse_args()
    al = load(a.aligned)
    rows = []
    for spec in a.truth_free:
        if "=" not in spec:
            sys.exit(f"in_flight_alignment: --truth-free '{spec}' is not LABEL=DIR")
        label, d = spec.split("=", 1)
        rows.append(row(label, load(d), al, a.diverged_deg))
    print(f"| truth-free start | runs | diverged (mean ‖Δr‖ > {a.diverged_deg:g}°) | worst mean / max ‖Δr‖ | "
          "mean ‖Δr‖, not diverged (aligned start, same runs) | final horizontal m (aligned) | final % (aligned) | "
          "declared aligned | time to align, s from t0: median [quartiles] |")
    print("|---|--:|--:|--:|--:|--:|--:|--:|--:|")
    for r in rows:
        print(f"| {r['label']} | {r['runs']} | {r['diverged']} | {r['worst_mean']:.1f}° / {r['worst_max']:.1f}° | "
              f"{r['att_ok']:.2f}° ({r['att_al']:.3f}°) | {r['hor_ok']:.0f} ({r['hor_al']:.0f}) | "
              f"{r['pct_ok']:.2f} ({r['pct_al']:.2f}) | {r['aligned']} | "
              f"{r['t_q'][1]:.0f} [{r['t_q'][0]:.0f}, {r['t_q'][2]:.0f}] |")
    if a.png:
        import matplotlib
        matplotlib.use("Agg")
        import matplotlib.pyplot as plt
        fig, (ax1, ax2) = plt.subplots(1, 2, figsize=(12, 5))
        for r, marker in zip(rows, "os^vD"):
            x, y = zip(*r["pairs"])
            ax1.scatter(x, y, s=14, marker=marker, alpha=0.7, label=f"{r['label']} ({r['diverged']} diverged)")
            if r["t_align"]:
                t = np.sort(r["t_align"])
                ax2.step(t, np.arange(1, len(t) + 1) / r["runs"], where="post", label=r["label"])
        lo, hi = 0.03, 200.0
        ax1.plot([lo, hi], [lo, hi], "k--", lw=0.8, label="equal")
        ax1.axhline(a.diverged_deg, color="r", lw=0.8, ls=":", label=f"diverged above {a.diverged_deg:g}°")
        ax1.set(xscale="log", yscale="log", xlim=(lo, hi), ylim=(lo, hi),
                xlabel="aligned start: mean attitude error ‖Δr‖ of the run [deg]",
                ylabel="truth-free start, same run [deg]", title="Each point a run")
        ax1.legend(fontsize=8)
        ax2.set(xlabel="time to align from t0 [s]", ylabel="fraction of the runs declared aligned",
                title="Time to align (runs never aligned: the curve stops below 1)", ylim=(0, 1))
        ax2.grid(alpha=0.3)
        ax2.legend(fontsize=8)
        fig.tight_layout()
        fig.savefig(a.png, dpi=110)
        print(f"\nfigure: {a.png}")


if __name__ == "__main__":
    main()
