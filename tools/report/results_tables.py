#!/usr/bin/python3
"""Every table of docs/results.md, regenerated from the batch directories.

usage: /usr/bin/python3 tools/report/results_tables.py ROOT [--update docs/results.md] [--figures DIR]

ROOT holds the batches of tools/report/comparison_batches.sh: ROOT/s1_NAME and ROOT/s2_NAME (NAME = base,
var_<variant>, band_<N>, grade_<group>_<grade>) and ROOT/provenance_s1.yaml / provenance_s2.yaml (command, commit).
Without --update the Markdown is printed; with it, each block between `<!-- table:KEY -->` and `<!-- /table -->`
in the file is replaced by the table KEY (keys: baseline_attitude, baseline_altitude, baseline_velocity,
baseline_horizontal, and per scenario S: sS_summary, sS_<group>, e.g. s2_attitude_variants). --figures DIR writes
sS_comparison.png (per-run mean attitude error and final horizontal error of every configuration).

Statistics are gdnav report's (common/core/metrics/aggregate.cpp): across runs, mean, population std and signed max
(largest |value|, sign kept) of each per-run metric; for per-run maxima, mean and std of |max|; non-finite values
skipped. A comparison group is aggregated over the run indices every batch of the group completed, so its
configurations fly the same missions; paired differences to the baseline are mean +- standard error over those runs.
Needs Debian's python3-yaml (python3-matplotlib for --figures); call /usr/bin/python3.
"""
import argparse
import math
import os
import re
import statistics
import sys

import yaml

from paper_stats import (DEG, agg, agg_abs_max, f, final_agg, group_table, num, pct, records, sig,
                         table)

HERE = os.path.dirname(os.path.abspath(__file__))

# Comparison groups: key, title, configurations (label, batch NAME), tables.
GROUPS = [
    ("attitude_variants", "Attitude filter variants (paper: Different Attitude Algorithms)",
     [("baseline", "base"), ("zero F_B derivatives", "var_att_zero_fb_derivatives"),
      ("zero F_N derivatives", "var_att_zero_fn_derivatives")], ["attitude"]),
    ("horizontal_variants", "Horizontal position variants (paper: Different Horizontal Position Algorithms)",
     [("baseline", "base"), ("double integration", "var_hor_double_integration"),
      ("wind integration", "var_hor_wind_integration")], ["velocity", "horizontal"]),
    ("vertical_variants", "Vertical position variants (paper: Different Vertical Position Algorithms)",
     [("baseline", "base"), ("integration", "var_ver_integration"),
      ("airspeed integration", "var_ver_airspeed_integration")], ["altitude"]),
    ("bias_bands", "Inertial bias-drift band (paper: Influence of Inertial Sensors Bias Stability)",
     [("±100 (baseline)", "base"), ("±300", "band_300"), ("±1000", "band_1000")],
     ["attitude", "velocity", "horizontal"]),
    ("gyroscopes", "Gyroscope grades (paper: Influence of Gyroscope Quality)",
     [("baseline", "base"), ("better", "grade_gyroscopes_better"), ("worse", "grade_gyroscopes_worse"),
      ("worst", "grade_gyroscopes_worst")], ["attitude", "horizontal"]),
    ("accelerometers", "Accelerometer grades (paper: Influence of Accelerometer Quality)",
     [("baseline", "base"), ("better", "grade_accelerometers_better"), ("worse", "grade_accelerometers_worse"),
      ("worst", "grade_accelerometers_worst")], ["attitude", "velocity", "horizontal"]),
    ("magnetometers", "Magnetometer grades (paper: Influence of Magnetometer Quality)",
     [("baseline", "base"), ("better", "grade_magnetometers_better"), ("worse", "grade_magnetometers_worse")],
     ["attitude", "horizontal"]),
    ("air_data", "Air data grades (paper: Influence of Air Data Sensors Quality)",
     [("baseline", "base"), ("better", "grade_air_data_better"), ("worse", "grade_air_data_worse")],
     ["attitude", "velocity", "horizontal"]),
    ("atmospheric", "Atmospheric sensor grades (paper: Influence of Atmospheric Sensors Quality)",
     [("baseline", "base"), ("worse", "grade_atmospheric_worse"), ("worst", "grade_atmospheric_worst")],
     ["altitude"]),
    ("new_filters", "Beyond the paper: error-state attitude filter and mean-wind freeze (issue 14)",
     [("baseline (paper's filter)", "base"), ("error-state", "var_att_error_state"),
      ("error-state + mean wind", "var_eskf_mean_wind")], ["attitude", "altitude", "velocity", "horizontal"]),
    ("truth_free", "Truth-free start (issue 14 item 1: init_mode measurements instead of the alignment)",
     [("alignment start (baseline)", "base"), ("truth-free, paper's filter", "tf_paper"),
      ("truth-free, error-state", "tf_error_state")], ["attitude", "altitude", "velocity", "horizontal"]),
]


class Batch:
    """The complete runs of one batch directory, by run index."""

    def __init__(self, path):
        self.path = path
        self.runs = {int(r["run_index"]): r for r in records(path)}

    def subset(self, indices):
        return [self.runs[i] for i in sorted(indices)]


def paired(base, other, key, stat, scale):
    """mean ± standard error of (other − base) over the common runs, and how many runs are better (smaller)."""
    d = [(sig(o, key, stat) - sig(b, key, stat)) * scale for b, o in zip(base, other)]
    d = [x for x in d if math.isfinite(x)]
    if len(d) < 2:
        return "n/a"
    se = statistics.stdev(d) / math.sqrt(len(d))
    better = sum(1 for x in d if x < 0)
    return f"{f(statistics.fmean(d), 4 if scale == DEG else 1, True)} ± {f(se, 4 if scale == DEG else 1)} ({better})"


def ordered_names(batches):
    """The batches in the order of GROUPS (baseline first), then any others alphabetically."""
    order = [n for _, _, cfgs, _ in GROUPS for _, n in cfgs]
    known = [n for n in dict.fromkeys(order) if n in batches]
    return known + sorted(n for n in batches if n not in known)


def summary_table(batches, runs):
    """One row per configuration: the headline figures and paired differences to the baseline."""
    base = batches["base"].subset(runs)
    rows = []
    for name in ordered_names(batches):
        recs = batches[name].subset(runs)
        att = agg([sig(r, "rot_rad", "mean") for r in recs])
        att_max = agg_abs_max([sig(r, "rot_rad", "max") for r in recs])
        hor = final_agg(recs, "hor_m")
        hp = agg([pct(r, "hor") for r in recs])
        rows.append([name, str(len(recs)), f(att["mean"] * DEG, 3), f(att_max["mean"] * DEG, 3),
                     f(final_agg(recs, "h_m")["std"], 2), f(final_agg(recs, "vn_mps")["std"], 2),
                     f(final_agg(recs, "ve_mps")["std"], 2), f(hor["mean"], 0), f(hp["mean"], 2), f(hp["std"], 2),
                     "—" if name == "base" else paired(base, recs, "rot_rad", "mean", DEG),
                     "—" if name == "base" else paired(base, recs, "hor_m", "final", 1.0)])
    return table(["configuration", "runs", "‖Δr̂‖ mean of run means [deg]", "‖Δr̂‖ mean of run max [deg]",
                  "ĥ−h final std [m]", "v̂_N−v_N final std [m/s]", "v̂_E−v_E final std [m/s]",
                  "Δx_hor final mean [m]", "[%]", "[%] std",
                  "Δ‖Δr̂‖ run mean vs baseline [deg] (runs better)", "ΔΔx_hor final vs baseline [m] (runs better)"],
                 rows)


# ---------------------------------------------------------------- baseline next to the paper
def baseline_tables(b1, b2, paper):
    """The four tables of docs/results.md's baseline section: paper #1, gdnav #1, paper #2, gdnav #2."""
    cols = [(paper["scenario1"], b1), (paper["scenario2"], b2)]
    hdr = ["", "paper #1", "gdnav #1", "paper #2", "gdnav #2"]
    n = [len(b1), len(b2)]

    def gd_att(recs, key, stat, over):
        vals = [sig(r, key, stat) for r in recs]
        a = agg_abs_max(vals) if stat == "max" else agg(vals)
        return a[over] * DEG

    att_rows = []
    for label, key, stat, over in [("mean of run means", "rot", "mean", "mean"), ("std of run means", "rot", "mean", "std"),
                                   ("max of run means", "rot", "mean", "max"), ("mean of run std", "rot", "std", "mean"),
                                   ("mean of run max", "rot", "max", "mean"),
                                   ("yaw error: mean of run std", "yaw", "std", "mean"),
                                   ("pitch error: mean of run std", "pitch", "std", "mean"),
                                   ("bank error: mean of run std", "bank", "std", "mean")]:
        row = [label]
        for p, recs in cols:
            row += [f(p["attitude"][key + "_deg"][stat][over], 3), f(gd_att(recs, key + "_rad", stat, over), 3)]
        att_rows.append(row)
    out = {"baseline_attitude": table(hdr, att_rows)}

    rows = []
    for stat in ("mean", "std", "max"):
        s = stat != "std"
        row = [stat]
        for p, recs in cols:
            row += [f(p["final_h_m"][stat], 2, s), f(final_agg(recs, "h_m")[stat], 2, s)]
        rows.append(row)
    out["baseline_altitude"] = table(hdr, rows)

    rows = []
    for stat in ("mean", "std", "max"):
        s = stat != "std"
        row = [stat]
        for p, recs in cols:
            row += [f"{f(p['final_vn_mps'][stat], 2, s)}, {f(p['final_ve_mps'][stat], 2, s)}",
                    f"{f(final_agg(recs, 'vn_mps')[stat], 2, s)}, {f(final_agg(recs, 've_mps')[stat], 2, s)}"]
        rows.append(row)
    out["baseline_velocity"] = table(hdr, rows)

    rows = []
    dist = ["distance since t_GNSS, mean [m]"]
    for p, recs in cols:
        dist += [f(p["distance_m"]["mean"], 0) + " (from t = 1 s)", f(agg([num(r["distance_since_gnss_m"]) for r in recs])["mean"], 0)]
    rows.append(dist)
    for label, unit, stat, digits in [("Δx_hor mean [m]", "m", "mean", 0), ("Δx_hor std [m]", "m", "std", 0),
                                      ("Δx_hor max [m]", "m", "max", 0), ("Δx_hor mean [%]", "pct", "mean", 2),
                                      ("Δx_hor std [%]", "pct", "std", 2)]:
        row = [label]
        for p, recs in cols:
            mine = final_agg(recs, "hor_m") if unit == "m" else agg([pct(r, "hor") for r in recs])
            row += [f(p["final_hor"][unit][stat], digits), f(mine[stat], digits)]
        rows.append(row)
    row = ["cross / along mean [%]"]
    for p, recs in cols:
        row += [f"{f(p['final_cross']['pct']['mean'], 2, True)} / {f(p['final_along']['pct']['mean'], 2, True)}",
                f"{f(agg([pct(r, 'cross') for r in recs])['mean'], 2, True)} / "
                f"{f(agg([pct(r, 'along') for r in recs])['mean'], 2, True)}"]
    rows.append(row)
    out["baseline_horizontal"] = table(hdr, rows)
    note = f"\n\n(gdnav: {n[0]} runs of #1, {n[1]} runs of #2; paper: 100 runs each.)"
    return {k: v + note for k, v in out.items()}


# ---------------------------------------------------------------- assembling
def provenance(root, s):
    path = os.path.join(root, f"provenance_s{s}.yaml")
    if not os.path.isfile(path):
        return None
    with open(path) as fh:
        return yaml.safe_load(fh)


def scenario_tables(root, s, batches):
    out = {}
    prov = provenance(root, s)
    names = list(batches)
    common = set.intersection(*(set(b.runs) for b in batches.values()))
    head = (f"Scenario #{s}: {len(common)} runs per configuration (run indices {min(common)}–{max(common)} of seed 1, "
            f"the same missions, winds and sensor draws in every configuration)")
    if prov:
        head += (f"; produced by `{prov.get('command')}` with gdnav at commit {str(prov.get('commit'))[:10]}"
                 + (" (" + str(prov['note']) + ")" if prov.get("note") else ""))
    out[f"s{s}_summary"] = head + ".\n\n" + summary_table(batches, common)
    for key, title, configs, kinds in GROUPS:
        present = [(label, name) for label, name in configs if name in batches]
        if len(present) < 2:
            continue
        runs = set.intersection(*(set(batches[n].runs) for _, n in present))
        blocks = [(label, batches[n].subset(runs)) for label, n in present]
        parts = [f"**{title}**, scenario #{s}, {len(runs)} runs each."]
        parts += [group_table(kind, blocks) for kind in kinds]
        out[f"s{s}_{key}"] = "\n\n".join(parts)
    missing = [n for _, _, cfgs, _ in GROUPS for _, n in cfgs if n not in names]
    if missing:
        print(f"results_tables.py: scenario #{s}: no batch for {', '.join(sorted(set(missing)))}", file=sys.stderr)
    return out


def load(root):
    by_s = {1: {}, 2: {}}
    for name in sorted(os.listdir(root)):
        m = re.fullmatch(r"s([12])_(.+)", name)
        if m and os.path.isdir(os.path.join(root, name, "runs")):
            b = Batch(os.path.join(root, name))
            if b.runs:
                by_s[int(m.group(1))][m.group(2)] = b
            print(f"results_tables.py: {name}: {len(b.runs)} complete runs", file=sys.stderr)
    return by_s


def figures(by_s, out_dir):
    import matplotlib
    import matplotlib.ticker
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    os.makedirs(out_dir, exist_ok=True)
    for s, batches in by_s.items():
        if "base" not in batches:
            continue
        runs = set.intersection(*(set(b.runs) for b in batches.values()))
        names = ordered_names(batches)
        att = [[sig(r, "rot_rad", "mean") * DEG for r in batches[n].subset(runs)] for n in names]
        hor = [[sig(r, "hor_m", "final") for r in batches[n].subset(runs)] for n in names]
        fig, axes = plt.subplots(1, 2, figsize=(13, 0.42 * len(names) + 1.6), sharey=True)
        for ax, data, xlabel in [(axes[0], att, "per-run mean of ‖Δr̂‖ [deg]"),
                                 (axes[1], hor, "final horizontal error [m]")]:
            ax.boxplot(data, vert=False, labels=names, showfliers=True, flierprops={"markersize": 3})
            ax.axvline(statistics.median(data[0]), color="grey", linestyle="--", linewidth=0.8)  # baseline median
            ax.set_xscale("log")
            ax.xaxis.set_major_locator(matplotlib.ticker.LogLocator(subs=(1.0, 2.0, 5.0)))
            ax.xaxis.set_major_formatter(
                matplotlib.ticker.FuncFormatter(lambda x, _: f"{x / 1000:g}k" if x >= 1000 else f"{x:g}"))
            ax.xaxis.set_minor_formatter(matplotlib.ticker.NullFormatter())
            ax.set_xlabel(xlabel)
            ax.grid(True, which="both", axis="x", alpha=0.3)
        axes[0].invert_yaxis()
        fig.suptitle(f"Scenario #{s}: every configuration on the same {len(runs)} runs (boxes: quartiles, "
                     f"whiskers 1.5 IQR; dashed: the baseline's median)")
        fig.tight_layout()
        path = os.path.join(out_dir, f"s{s}_comparison.png")
        fig.savefig(path, dpi=110)
        plt.close(fig)
        print(f"results_tables.py: wrote {path}", file=sys.stderr)


def update(path, tables):
    with open(path) as fh:
        text = fh.read()
    used = set()

    def repl(m):
        key = m.group(1)
        if key not in tables:
            print(f"results_tables.py: {path}: no table '{key}' from these batches; block left as it was",
                  file=sys.stderr)
            return m.group(0)
        used.add(key)
        return f"<!-- table:{key} -->\n{tables[key]}\n<!-- /table -->"

    text = re.sub(r"<!-- table:([a-z0-9_]+) -->\n.*?<!-- /table -->", repl, text, flags=re.S)
    with open(path, "w") as fh:
        fh.write(text)
    print(f"results_tables.py: {path}: replaced {len(used)} tables; not in the file: "
          f"{', '.join(sorted(set(tables) - used)) or 'none'}", file=sys.stderr)


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("root")
    ap.add_argument("--update", metavar="MARKDOWN")
    ap.add_argument("--figures", metavar="DIR")
    ap.add_argument("--baseline1", help="batch for the baseline table of #1 (default ROOT/s1_base)")
    ap.add_argument("--baseline2", help="batch for the baseline table of #2 (default ROOT/s2_base)")
    a = ap.parse_args()
    if not os.path.isdir(a.root):
        sys.exit(f"results_tables.py: {a.root}: no such directory")
    by_s = load(a.root)
    tables = {}
    for s in (1, 2):
        if "base" in by_s[s]:
            tables.update(scenario_tables(a.root, s, by_s[s]))
    b1 = Batch(a.baseline1) if a.baseline1 else by_s[1].get("base")
    b2 = Batch(a.baseline2) if a.baseline2 else by_s[2].get("base")
    if b1 and b2:
        with open(os.path.join(HERE, "paper_tables.yaml")) as fh:
            paper = yaml.safe_load(fh)
        tables.update(baseline_tables(list(b1.subset(b1.runs)), list(b2.subset(b2.runs)), paper))
    if not tables:
        sys.exit(f"results_tables.py: no sS_base batch in {a.root}")
    if a.figures:
        figures(by_s, a.figures)
    if a.update:
        update(a.update, tables)
    else:
        for k in sorted(tables):
            print(f"<!-- table:{k} -->\n{tables[k]}\n<!-- /table -->\n")


if __name__ == "__main__":
    main()
