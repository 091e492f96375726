"""Loading a gdnav Monte Carlo batch: its complete runs, their metrics and run.h5 tables (docs/montecarlo.md).

Shared by report.py (PNG figures) and review.py (HTML flight review pages). Debian's python3-yaml, -numpy, -h5py.
"""
import csv
import math
import os

import h5py
import numpy as np
import yaml

from paper_stats import DamagedRun, damaged, run_damage  # noqa: F401 (DamagedRun: for the callers)

DEG = 180.0 / math.pi


def load_runs(batch):
    """Complete runs of BATCH/runs/run_*: dicts {index, metrics (metrics.yaml), h5, dir}, sorted by run index.
    Raises DamagedRun for a run whose files differ from its files.yaml or whose run.h5 cannot be opened."""
    runs = []
    root = os.path.join(batch, "runs")
    for name in sorted(os.listdir(root)) if os.path.isdir(root) else []:
        d = os.path.join(root, name)
        m, h = os.path.join(d, "metrics.yaml"), os.path.join(d, "run.h5")
        if not (os.path.isfile(m) and os.path.isfile(h)):
            continue
        with open(m) as f:
            rec = yaml.safe_load(f)
        if rec.get("complete") is True:
            index = int(rec["run_index"])
            why = run_damage(d)
            if not why:
                try:
                    h5py.File(h, "r").close()
                except OSError as e:
                    why = f"run.h5 cannot be read ({str(e).splitlines()[0]})"
            if why:
                raise damaged(d, index, why)
            runs.append({"index": index, "metrics": rec, "h5": h, "dir": d})
    runs.sort(key=lambda r: r["index"])
    return runs


def load_failures(batch):
    """Failed runs of BATCH/runs/run_* (their failure.yaml, written by gdnav montecarlo): dicts {run, exit_code,
    cause, log_tail, member_logs}, sorted by run index."""
    failures = []
    root = os.path.join(batch, "runs")
    for name in sorted(os.listdir(root)) if os.path.isdir(root) else []:
        f = os.path.join(root, name, "failure.yaml")
        if os.path.isfile(f):
            with open(f) as fh:
                rec = yaml.safe_load(fh) or {}
            if "run" in rec:
                failures.append(rec)
    failures.sort(key=lambda r: int(r["run"]))
    return failures


def signal(rec, key, stat):
    """One per-run statistic of an error signal from a metrics.yaml record (NaN when undefined)."""
    v = rec["signals"][key][stat]
    return float(v) if v is not None else float("nan")


def final_distance(rec):
    """The distance a run's final percentages divide by: flown since t_GNSS up to t_end when an estimator stopped
    before the end (metrics.yaml estimates_complete: false), else to the end of the flight."""
    if rec.get("estimates_complete", True) is False:
        return float(rec["distance_at_t_end_m"])
    return float(rec["distance_since_gnss_m"])


def stopped_note(rec):
    """'' for a run whose estimates reach the end; else which estimates stopped and when (metrics.yaml)."""
    if rec.get("estimates_complete", True) is not False:
        return ""
    last = {k: float("nan") if v is None else float(v) for k, v in (rec.get("last_estimate_s") or {}).items()}
    latest = max([v for v in last.values() if math.isfinite(v)], default=float("nan"))
    # The estimates last seen before the others stopped (or never came).
    gone = [f"{k} at t = {v:.2f} s" if math.isfinite(v) else f"{k} never" for k, v in last.items()
            if not math.isfinite(v) or v < latest]
    t_end = float(rec.get("t_end_s", float("nan")))
    return f"estimator stopped ({', '.join(gone) or f'all at t = {latest:.2f} s'}): figures over [0, {t_end:.2f}] s"


def read_runs_csv(path):
    """Rows of runs.csv by run index; `distance` is what the run's final % divides by (up to t_end when an
    estimator stopped; runs.csv of an older gdnav has no distance_at_t_end_m)."""
    with open(path, newline="") as f:
        rows = {int(r["run_index"]): {k: float(v) for k, v in r.items()} for r in csv.DictReader(f)}
    for v in rows.values():
        v["distance"] = v.get("distance_at_t_end_m", v["distance_since_gnss_m"])
    return rows


def batch_label(batch):
    """The batch folder's name, with 'scenario #1' / 'scenario #2' for the paper generators (batch.yaml) or the
    scenario's name when it differs from the folder's (as gdnav report's tables)."""
    folder = os.path.basename(os.path.abspath(batch))
    what = ""
    try:
        with open(os.path.join(batch, "batch.yaml")) as f:
            rec = yaml.safe_load(f) or {}
        what = {"paper_scenario1": "scenario #1", "paper_scenario2": "scenario #2"}.get(rec.get("generator"),
                                                                                         str(rec.get("scenario", "")))
    except OSError:
        pass
    return folder if not what or what == folder else f"{folder} ({what})"


def read_table(path, name, columns):
    """Columns of the run.h5 table NAME (with its t_s) and the file's t_gnss_s attribute: (t, {col: array}, t_gnss)."""
    with h5py.File(path, "r") as f:
        e = f[name]
        t = e["t_s"][:]
        cols = {c: e[c][:] for c in columns}
        t_gnss = float(f.attrs.get("t_gnss_s", 100.0))
    return t, cols, t_gnss


class Streamed:
    """Across-run mean and population std per time sample of the given columns, one run at a time. A sample without
    a value (NaN: a run whose estimator stopped) is left out of that time's mean and std."""

    def __init__(self, columns):
        self.columns = list(columns)
        self.n = 0
        self.t = None
        self.s1 = {}
        self.s2 = {}
        self.count = {}

    def add(self, t, err):
        if self.t is None:
            self.t = t
            for c in self.columns:
                self.s1[c] = np.zeros_like(t)
                self.s2[c] = np.zeros_like(t)
                self.count[c] = np.zeros_like(t)
        m = min(len(self.t), len(t))
        if m < len(self.t):  # a shorter run: keep the common time span
            self.t = self.t[:m]
            for c in self.columns:
                self.s1[c], self.s2[c], self.count[c] = self.s1[c][:m], self.s2[c][:m], self.count[c][:m]
        for c in self.columns:
            x = err[c][:m]
            ok = np.isfinite(x)
            x = np.where(ok, x, 0.0)
            self.s1[c] += x
            self.s2[c] += x * x
            self.count[c] += ok
        self.n += 1

    def mean_std(self, c):
        with np.errstate(invalid="ignore", divide="ignore"):
            n = np.where(self.count[c] > 0, self.count[c], np.nan)
            mean = self.s1[c] / n
            var = np.maximum(self.s2[c] / n - mean * mean, 0.0)
        return mean, np.sqrt(var)
