"""Loading a gdnav Monte Carlo batch: its complete runs, their metrics and run.h5 tables (docs/montecarlo.md).

Shared by report.py (PNG figures) and review.py (HTML flight review pages). Debian's python3-yaml, -numpy, -h5py.
"""
import math
import os

import h5py
import numpy as np
import yaml

DEG = 180.0 / math.pi


def load_runs(batch):
    """Complete runs of BATCH/runs/run_*: dicts {index, metrics (metrics.yaml), h5, dir}, sorted by run index."""
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
            runs.append({"index": int(rec["run_index"]), "metrics": rec, "h5": h, "dir": d})
    runs.sort(key=lambda r: r["index"])
    return runs


def signal(rec, key, stat):
    """One per-run statistic of an error signal from a metrics.yaml record (NaN when undefined)."""
    v = rec["signals"][key][stat]
    return float(v) if v is not None else float("nan")


def batch_label(batch):
    """'scenario #1' / 'scenario #2' for the paper generators (batch.yaml), else the folder name."""
    label = os.path.basename(os.path.normpath(batch))
    try:
        with open(os.path.join(batch, "batch.yaml")) as f:
            gen = (yaml.safe_load(f) or {}).get("generator", "")
        label = {"paper_scenario1": "scenario #1", "paper_scenario2": "scenario #2"}.get(gen, label)
    except OSError:
        pass
    return label


def read_table(path, name, columns):
    """Columns of the run.h5 table NAME (with its t_s) and the file's t_gnss_s attribute: (t, {col: array}, t_gnss)."""
    with h5py.File(path, "r") as f:
        e = f[name]
        t = e["t_s"][:]
        cols = {c: e[c][:] for c in columns}
        t_gnss = float(f.attrs.get("t_gnss_s", 100.0))
    return t, cols, t_gnss


class Streamed:
    """Across-run mean and population std per time sample of the given columns, one run at a time."""

    def __init__(self, columns):
        self.columns = list(columns)
        self.n = 0
        self.t = None
        self.s1 = {}
        self.s2 = {}

    def add(self, t, err):
        if self.t is None:
            self.t = t
            for c in self.columns:
                self.s1[c] = np.zeros_like(t)
                self.s2[c] = np.zeros_like(t)
        m = min(len(self.t), len(t))
        if m < len(self.t):  # a shorter run: keep the common time span
            self.t = self.t[:m]
            for c in self.columns:
                self.s1[c], self.s2[c] = self.s1[c][:m], self.s2[c][:m]
        for c in self.columns:
            x = err[c][:m]
            self.s1[c] += x
            self.s2[c] += x * x
        self.n += 1

    def mean_std(self, c):
        mean = self.s1[c] / self.n
        var = np.maximum(self.s2[c] / self.n - mean * mean, 0.0)
        return mean, np.sqrt(var)
