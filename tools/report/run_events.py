"""What happened during one gdnav run, for its flight review page: faults, GNSS state, logged events.

Sources (all optional, in the run folder): run.yaml (`faults:` as scheduled) or faults.yaml (as applied, written by
the clock of a distributed run with live faults; it wins), log.txt (the run's log: lines of components that name their
step, e.g. "[nav_pos] step 15151 t=101.51 s: GNSS lost: ..."; warnings and errors), clock_summary.yaml (members
declared dead, rejoined, the abort reason), and run.h5 (/gnss fix epochs, /estimate gnss_denied).
"""
import os
import re

import numpy as np
import yaml

_TIMED = re.compile(r"\[(?P<comp>[^\]\[]+)\] step (?P<step>\d+) t=(?P<t>-?[0-9.]+) s: (?P<msg>.*)$")
_LEVEL = re.compile(r"^\[[0-9:.]+\] \[[^\]]+\] (?P<level>[a-z]+): (?P<rest>.*)$")


def faults(run_dir):
    """The run's fault list (faults.yaml as applied if present, else run.yaml's schedule) and where it came from."""
    for name in ("faults.yaml", "run.yaml"):
        p = os.path.join(run_dir, name)
        if os.path.isfile(p):
            with open(p) as f:
                doc = yaml.safe_load(f) or {}
            if name == "faults.yaml" or doc.get("faults"):
                return list(doc.get("faults") or []), name
    return [], None


def fault_label(f):
    what = f"{f.get('kind', '?')} of {f.get('target', '?')}"
    if f.get("topic"):
        what += f" ({f['topic']})"
    fields = f.get("fields")
    if isinstance(fields, dict):
        what += " " + ", ".join(f"{k} {v}" for k, v in fields.items())
    elif fields:
        what += " " + ", ".join(str(v) for v in fields)
    for k in ("steps", "p"):
        if k in f:
            what += f" {k} {f[k]}"
    return what


def log_events(run_dir):
    """Timed component events of log.txt: [(t_s, component, level, message)]; and the untimed warnings/errors."""
    timed, untimed = [], []
    p = os.path.join(run_dir, "log.txt")
    if not os.path.isfile(p):
        return timed, untimed
    with open(p, errors="replace") as f:
        for line in f:
            line = line.rstrip("\n")
            lv = _LEVEL.match(line)
            level = lv.group("level") if lv else ""
            m = _TIMED.search(line)
            if m:
                timed.append((float(m.group("t")), m.group("comp"), level, m.group("msg")))
            elif level in ("warning", "warn", "error", "critical"):
                untimed.append((level, lv.group("rest")))
    return timed, untimed


def clock_notes(run_dir):
    """Lines about the run's members from clock_summary.yaml (dead, rejoined, abort reason); [] when all is well."""
    p = os.path.join(run_dir, "clock_summary.yaml")
    if not os.path.isfile(p):
        return []
    with open(p) as f:
        doc = yaml.safe_load(f) or {}
    notes = []
    for key, text in (("dead_members", "members declared dead"), ("rejoined_members", "members that rejoined")):
        if doc.get(key):
            notes.append(f"{text}: {doc[key]}")
    if doc.get("abort_reason"):
        notes.append(f"run aborted: {doc['abort_reason']}")
    if doc.get("completed") is False:
        notes.append("the clock did not complete the run")
    return notes


def intervals(t, flag):
    """[(start, end)] of the times where FLAG (0/1 samples at times T) is set."""
    on = np.nan_to_num(np.asarray(flag, dtype=float)) > 0.5
    out, start = [], None
    for ti, o in zip(t, on):
        if o and start is None:
            start = ti
        elif not o and start is not None:
            out.append((start, ti))
            start = None
    if start is not None:
        out.append((start, t[-1]))
    return out
