"""The paper's per-batch statistics and tables from the runs' metrics.yaml, shared by results_tables.py (docs/results.md)
and compare.py (gdnav compare).

Statistics are gdnav report's (common/core/metrics/aggregate.cpp): across runs, mean, population std and signed max
(largest |value|, sign kept) of each per-run metric; for per-run maxima, mean and std of |max|; non-finite values
skipped, and a statistic without any value printed "n/a". Needs Debian's python3-yaml.
"""
import math
import os
import statistics

import yaml

DEG = 180.0 / math.pi


class DamagedRun(Exception):
    """A complete run whose files are not those it wrote: one line naming the run and what differs."""


def run_damage(run_dir):
    """What differs between RUN_DIR's files and the sizes its files.yaml recorded when the run ended (gdnav
    montecarlo; docs/montecarlo.md, "Damaged runs and a full disk"), or "" (also for a run of a batch older than
    files.yaml)."""
    listed = os.path.join(run_dir, "files.yaml")
    if not os.path.isfile(listed):
        return ""
    try:
        with open(listed) as fh:
            entries = (yaml.safe_load(fh) or {}).get("files") or {}
    except (OSError, yaml.YAMLError) as e:
        return f"files.yaml is unreadable ({e})"
    for rel, entry in sorted(entries.items()):
        path = os.path.join(run_dir, rel)
        if not os.path.isfile(path):
            return f"{rel} is missing"
        size, want = os.path.getsize(path), int((entry or {}).get("size", -1))
        if size != want:
            return f"{rel} has {size} bytes, {want} when the run ended"
    return ""


def damaged(run_dir, index, why):
    return DamagedRun(f"run {index} ({run_dir}) is damaged: {why}; run the batch's gdnav montecarlo command again "
                      "to rerun it")


def records(batch):
    """The metrics.yaml records of the complete runs of BATCH/runs/run_*, in folder order."""
    root = os.path.join(batch, "runs")
    out = []
    for name in sorted(os.listdir(root)) if os.path.isdir(root) else []:
        path = os.path.join(root, name, "metrics.yaml")
        if os.path.isfile(path):
            with open(path) as f:
                rec = yaml.safe_load(f)
            if isinstance(rec, dict) and rec.get("complete") is True:
                out.append(rec)
    return out


def agg(values):
    v = [x for x in values if x is not None and math.isfinite(x)]
    if not v:
        return {"mean": float("nan"), "std": float("nan"), "max": float("nan"), "n": 0}
    return {"mean": statistics.fmean(v), "std": statistics.pstdev(v), "max": max(v, key=abs), "n": len(v)}


def agg_abs_max(values):
    a = agg([abs(x) for x in values])
    a["max"] = agg(values)["max"]
    return a


def num(v):
    return float(v) if v is not None else float("nan")


def sig(rec, key, stat):
    return num(rec["signals"][key][stat])


def pct(rec, key):
    return num(rec["final_percent"][key])


# ---------------------------------------------------------------- formatting
def f(x, digits, signed=False):
    if x is None or not math.isfinite(x):
        return "n/a"
    if round(x, digits) == 0:
        x = 0.0  # no "−0.000": a value that rounds to zero is printed unsigned
        signed = False
    s = f"{x:+,.{digits}f}" if signed else f"{x:,.{digits}f}"
    return s.replace(",", " ").replace("-", "−")


def table(header, rows):
    out = ["| " + " | ".join(header) + " |", "|---|" + "--:|" * (len(header) - 1)]
    out += ["| " + " | ".join(r) + " |" for r in rows]
    return "\n".join(out)


def attitude_rows(recs):
    """Paper layout (tab:attitude_errors): for mean, std, max across runs, the Euler angle errors' per-run mean
    and std and ‖Δr̂‖'s per-run mean, std and max|.|, in degrees."""
    cols = []
    for key in ("yaw_rad", "pitch_rad", "bank_rad"):
        cols.append((agg([sig(r, key, "mean") for r in recs]), True))
        cols.append((agg([sig(r, key, "std") for r in recs]), False))
    cols.append((agg([sig(r, "rot_rad", "mean") for r in recs]), False))
    cols.append((agg([sig(r, "rot_rad", "std") for r in recs]), False))
    cols.append((agg_abs_max([sig(r, "rot_rad", "max") for r in recs]), False))
    rows = []
    for stat in ("mean", "std", "max"):
        rows.append([stat] + [f(a[stat] * DEG, 3, signed and stat != "std") for a, signed in cols])
    return rows


ATT_HEADER = ["ψ̂−ψ mean", "ψ̂−ψ std", "θ̂−θ mean", "θ̂−θ std", "ξ̂−ξ mean", "ξ̂−ξ std", "‖Δr̂‖ mean",
              "‖Δr̂‖ std", "‖Δr̂‖ max\\|·\\|"]


def final_agg(recs, key):
    return agg([sig(r, key, "final") for r in recs])


def group_table(kind, blocks):
    """blocks: [(label, recs)] -> one Markdown table of kind attitude/altitude/velocity/horizontal."""
    if kind == "attitude":
        rows = []
        for label, recs in blocks:
            for i, r in enumerate(attitude_rows(recs)):
                rows.append([label if i == 0 else ""] + r)
        return ("Body attitude NSE [deg] (across runs: mean / std / max of each per-run metric)\n\n" +
                table(["configuration", ""] + ATT_HEADER, rows))
    if kind == "altitude":
        rows = []
        for stat in ("mean", "std", "max"):
            rows.append([stat] + [f(final_agg(recs, "h_m")[stat], 2, stat != "std") for _, recs in blocks])
        return "Final geometric altitude ĥ − h [m]\n\n" + table([""] + [b[0] for b in blocks], rows)
    if kind == "velocity":
        rows = []
        for stat in ("mean", "std", "max"):
            rows.append([stat] + [f"{f(final_agg(recs, 'vn_mps')[stat], 2, stat != 'std')}, "
                                  f"{f(final_agg(recs, 've_mps')[stat], 2, stat != 'std')}" for _, recs in blocks])
        return "Final ground velocity v̂ − v [m/s] (N, E)\n\n" + table([""] + [b[0] for b in blocks], rows)
    if kind == "horizontal":
        rows = []
        for label, recs in blocks:
            d = agg([num(r["distance_since_gnss_m"]) for r in recs])
            cm, cp = final_agg(recs, "cross_m"), agg([pct(r, "cross") for r in recs])
            am, ap = final_agg(recs, "along_m"), agg([pct(r, "along") for r in recs])
            hm, hp = final_agg(recs, "hor_m"), agg([pct(r, "hor") for r in recs])
            for i, stat in enumerate(("mean", "std", "max")):
                s = stat != "std"
                rows.append([label if i == 0 else "", stat, f(d[stat], 0), f(cm[stat], 0, s), f(cp[stat], 2, s),
                             f(am[stat], 0, s), f(ap[stat], 2, s), f(hm[stat], 0), f(hp[stat], 2)])
        return ("Final horizontal position (distance since t_GNSS; cross/along signed; Δx_hor a norm)\n\n" +
                table(["configuration", "", "distance [m]", "Δx_cross [m]", "[%]", "Δx_along [m]", "[%]",
                       "Δx_hor [m]", "[%]"], rows))
    raise ValueError(kind)
