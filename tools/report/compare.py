#!/usr/bin/python3
"""Paired comparison of gdnav Monte Carlo batches that flew the same missions (what `gdnav compare` runs).

usage: /usr/bin/python3 tools/report/compare.py BASE CANDIDATE [CANDIDATE ...] [--labels a,b,c] [--out DIR]

Reads each batch folder of `gdnav montecarlo` (batch.yaml, runs/run_*/metrics.yaml of the complete runs and their
drawn_scenario.yaml) and prints Markdown on stdout:
  - the paper's tables for each batch over the runs every batch completed (body attitude: mean / std / max across
    runs of the run means, stds and maxima; final altitude; final ground velocity N, E; final horizontal position
    in m and %), as docs/results.md;
  - for each candidate, paired differences candidate - base over the runs both flew: mean +- standard error, runs
    in which the candidate is better (smaller error), and the two-sided Wilcoxon signed-rank p-value
    (scipy.stats.wilcoxon: exact for up to 50 pairs without zero differences, else the normal approximation).
With --out DIR it also writes DIR/compare.html: a paired scatter per metric (each point a run, linking to that run's
review page: BATCH/report/review/run_NNNN.html when `gdnav report` made it, else one written into DIR/review/) and
the across-run mean +- sigma of the errors over time for every batch (compare_page.py).

Batches pair only when they flew the same missions: the same scenario generator (or, without one, scenario file),
the same seed and number of steps, run indices in common and, run by run, the same drawn scenario (SHA-256 of
drawn_scenario.yaml).
Otherwise, and for bad input (not a batch, no complete run, a wrong number of labels), one line on stderr and exit
code 2. Batches recorded before gdnav wrote drawn_scenario.yaml are paired by scenario, seed and run indices, with one
warning line. A metric without a value in a run (a run that ended before the GNSS loss) is "n/a".
Needs Debian's python3-yaml and python3-scipy (python3-matplotlib, -numpy, -h5py, -plotly for --out); call
/usr/bin/python3.
"""
import argparse
import hashlib
import math
import os
import statistics
import sys
import warnings

import yaml

from paper_stats import DEG, damaged, f, group_table, pct, records, run_damage, sig

# Paired metrics: key, label, unit, value of a run (smaller is better), decimals.
PAIRED = [
    ("att_mean", "‖Δr̂‖ run mean", "deg", lambda r: sig(r, "rot_rad", "mean") * DEG, 4),
    ("att_std", "‖Δr̂‖ run std", "deg", lambda r: sig(r, "rot_rad", "std") * DEG, 4),
    ("att_max", "‖Δr̂‖ run max", "deg", lambda r: abs(sig(r, "rot_rad", "max")) * DEG, 4),
    ("h_final", "\\|ĥ−h\\| final", "m", lambda r: abs(sig(r, "h_m", "final")), 2),
    ("vn_final", "\\|v̂_N−v_N\\| final", "m/s", lambda r: abs(sig(r, "vn_mps", "final")), 3),
    ("ve_final", "\\|v̂_E−v_E\\| final", "m/s", lambda r: abs(sig(r, "ve_mps", "final")), 3),
    ("hor_m", "Δx_hor final", "m", lambda r: sig(r, "hor_m", "final"), 1),
    ("hor_pct", "Δx_hor final", "%", lambda r: pct(r, "hor"), 3),
]


class InputError(Exception):
    """Bad input or batches that cannot be paired: one line, exit code 2."""


class Batch:
    """A batch folder: batch.yaml and its complete runs by run index, each with the SHA-256 of its drawn scenario."""

    def __init__(self, path, label):
        self.path, self.label = path, label
        if not os.path.isdir(os.path.join(path, "runs")):
            raise InputError(f"{path} is not a gdnav montecarlo batch (no runs/ folder)")
        self.info = {}
        if os.path.isfile(os.path.join(path, "batch.yaml")):
            with open(os.path.join(path, "batch.yaml")) as fh:
                self.info = yaml.safe_load(fh) or {}
        self.runs, self.dirs, self.digests = {}, {}, {}
        for rec in records(path):
            i = int(rec["run_index"])
            self.runs[i] = rec
            self.dirs[i] = os.path.join(path, "runs", f"run_{i:04d}")
            why = run_damage(self.dirs[i])
            if why:
                raise InputError(str(damaged(self.dirs[i], i, why)))
            drawn = os.path.join(self.dirs[i], "drawn_scenario.yaml")
            if os.path.isfile(drawn):
                with open(drawn, "rb") as fh:
                    self.digests[i] = hashlib.sha256(fh.read()).hexdigest()
        if not self.runs:
            raise InputError(f"{path}: no complete run (runs/run_*/metrics.yaml with complete: true)")

    def scenario(self):
        gen = str(self.info.get("generator", "none"))
        return gen if gen != "none" else os.path.basename(str(self.info.get("file", "?")))


def default_labels(paths):
    """The batch folders' names; with the parent folder's name where two would be the same."""
    names = [os.path.basename(os.path.abspath(p)) for p in paths]
    return [os.path.join(os.path.basename(os.path.dirname(os.path.abspath(p))), n) if names.count(n) > 1 else n
            for p, n in zip(paths, names)]


def ranges(indices):
    """'0-2, 5' for [0, 1, 2, 5]."""
    out, run = [], []
    for i in sorted(indices):
        if run and i != run[-1] + 1:
            out.append(run)
            run = []
        run.append(i)
    out += [run] if run else []
    return ", ".join(f"{r[0]}-{r[-1]}" if len(r) > 1 else str(r[0]) for r in out)


def pairing_problem(base, cand):
    """Why BASE and CAND did not fly the same missions ('' when they did), and the runs whose drawn scenario was
    not recorded by both."""
    if base.scenario() != cand.scenario():
        return f"different scenarios ({base.scenario()} and {cand.scenario()})", []
    common = sorted(set(base.runs) & set(cand.runs))
    if not common:
        return (f"no run index in common (runs {ranges(base.runs)} and {ranges(cand.runs)})"), []
    for i in common:
        for key, what in (("seed", "seeds"), ("steps", "run lengths (steps)")):
            vb, vc = base.runs[i].get(key), cand.runs[i].get(key)
            if vb != vc:
                return f"different {what} ({vb} and {vc}, run {i})", []
    unchecked = []
    for i in common:
        db, dc = base.digests.get(i), cand.digests.get(i)
        if db is None or dc is None:
            unchecked.append(i)
        elif db != dc:
            return (f"run {i} drew different scenarios (SHA-256 of drawn_scenario.yaml {db[:12]}... and "
                    f"{dc[:12]}...)"), []
    return "", unchecked


def paired_stats(base_values, cand_values):
    """Paired differences cand - base over the pairs where both are finite: n, mean, standard error (sample std /
    sqrt(n)), runs better (cand < base), two-sided Wilcoxon signed-rank p (NaN when undefined: n < 2, all equal)."""
    from scipy.stats import wilcoxon
    d = [c - b for b, c in zip(base_values, cand_values) if math.isfinite(b) and math.isfinite(c)]
    nan = float("nan")
    out = {"n": len(d), "mean": statistics.fmean(d) if d else nan,
           "se": statistics.stdev(d) / math.sqrt(len(d)) if len(d) >= 2 else nan,
           "better": sum(1 for x in d if x < 0), "p": nan}
    if len(d) >= 2 and any(x != 0 for x in d):
        with warnings.catch_warnings():  # zero differences: scipy warns that it takes the normal approximation
            warnings.simplefilter("ignore")
            out["p"] = float(wilcoxon(d).pvalue)
    return out


def p_text(p):
    if not math.isfinite(p):
        return "n/a"
    return f"{p:.2g}" if p >= 1e-4 else "< 1e-4"


def paired_table(base, cand, runs):
    """Markdown: one row per paired metric of CAND against BASE over RUNS."""
    rows = ["| metric | " + base.label + " mean | " + cand.label + " mean | difference, mean ± s.e. | runs better "
            "| Wilcoxon p |", "|---|--:|--:|--:|--:|--:|"]
    for _, label, unit, value, digits in PAIRED:
        b = [value(base.runs[i]) for i in runs]
        c = [value(cand.runs[i]) for i in runs]
        s = paired_stats(b, c)
        both = [(x, y) for x, y in zip(b, c) if math.isfinite(x) and math.isfinite(y)]
        mb = statistics.fmean(x for x, _ in both) if both else float("nan")
        mc = statistics.fmean(y for _, y in both) if both else float("nan")
        diff = "n/a" if s["n"] == 0 else f"{f(s['mean'], digits, True)} ± {f(s['se'], digits)}"
        better = "n/a" if s["n"] == 0 else f"{s['better']} of {s['n']}"
        rows.append(f"| {label} [{unit}] | {f(mb, digits)} | {f(mc, digits)} | {diff} | {better} | "
                    f"{p_text(s['p'])} |")
    return "\n".join(rows)


def markdown(batches, common, pairs):
    """The whole report: the per-batch tables over COMMON, then each candidate's paired differences."""
    base = batches[0]
    out = ["# Paired comparison of gdnav batches", ""]
    for b in batches:
        out.append(f"- {b.label}: {b.path} ({len(b.runs)} complete runs, scenario {b.scenario()}, seed "
                   f"{b.info.get('seed', '?')})")
    out += ["", f"## The paper's tables over the {len(common)} runs every batch completed (runs {ranges(common)})",
            "", "Across runs: mean, population std and max (largest |value|, sign kept) of each per-run metric; "
            "n/a where no run has a value (runs that ended before the GNSS loss).", ""]
    blocks = [(b.label, [b.runs[i] for i in common]) for b in batches]
    for kind in ("attitude", "altitude", "velocity", "horizontal"):
        out += [group_table(kind, blocks), ""]
    for cand, runs in pairs:
        n = f"{len(runs)} run" + ("s" if len(runs) != 1 else "")
        out += [f"## {cand.label} against {base.label}: paired over {n} (runs {ranges(runs)})", "",
                f"Difference = {cand.label} − {base.label}, run by run (negative: {cand.label} better); s.e. = "
                "sample std / √n; runs better: runs with a smaller error; Wilcoxon signed-rank test, two-sided. "
                "Signed errors (altitude, velocity) are compared by magnitude.", "", paired_table(base, cand, runs),
                ""]
    return "\n".join(out)


def parse(argv):
    p = argparse.ArgumentParser(prog="gdnav compare", description=__doc__.split("\n")[0])
    p.add_argument("batches", nargs="+", metavar="BATCH", help="BASE CANDIDATE [CANDIDATE...]")
    p.add_argument("--labels", help="comma-separated labels, one per batch (default: the folder names)")
    p.add_argument("--out", help="folder of the HTML page (compare.html) and its figures")
    p.add_argument("--no-run-pages", action="store_true",
                   help="link runs without a review page to their folder instead of writing their page")
    a = p.parse_args(argv)
    if len(a.batches) < 2:
        raise InputError("give a base batch and at least one candidate batch")
    labels = a.labels.split(",") if a.labels is not None else default_labels(a.batches)
    if len(labels) != len(a.batches) or any(not s.strip() for s in labels):
        raise InputError(f"--labels gives {len(labels)} label(s) for {len(a.batches)} batches (one non-empty label "
                         "per batch, comma-separated)")
    if len(set(labels)) != len(labels):
        raise InputError(f"two batches have the same label ({', '.join(labels)}); give --labels")
    return a, [s.strip() for s in labels]


def run(argv):
    a, labels = parse(argv)
    batches = [Batch(path, label) for path, label in zip(a.batches, labels)]
    base, pairs, unchecked = batches[0], [], set()
    for cand in batches[1:]:
        problem, missing = pairing_problem(base, cand)
        if problem:
            raise InputError(f"{cand.path} and {base.path} did not fly the same missions: {problem}")
        pairs.append((cand, sorted(set(base.runs) & set(cand.runs))))
        unchecked.update(missing)
    if unchecked:
        print(f"compare: warning: {len(unchecked)} paired run(s) without a recorded drawn scenario "
              "(drawn_scenario.yaml; batches of an older gdnav): their drawn scenarios could not be checked, only "
              "scenario, seed and run indices", file=sys.stderr)
    common = sorted(set.intersection(*(set(b.runs) for b in batches)))
    text = markdown(batches, common, pairs)
    print(text)
    if a.out:
        import compare_page  # matplotlib, h5py, plotly: only for the page
        path = compare_page.write(a.out, batches, pairs, PAIRED, common, text, not a.no_run_pages)
        print(f"compare: page written to {path}", file=sys.stderr)
    return 0


def main(argv=None):
    try:
        return run(sys.argv[1:] if argv is None else argv)
    except InputError as e:
        print(f"compare: {e}", file=sys.stderr)
        return 2


if __name__ == "__main__":
    sys.exit(main())
