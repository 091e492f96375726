#!/usr/bin/python3
"""Interactive flight review pages of a gdnav Monte Carlo batch (HTML that opens offline, plotly).

usage: /usr/bin/python3 tools/report/review.py BATCH_DIR [--out DIR] [--tables FILE] [--runs-csv FILE] [--jobs N]
       /usr/bin/python3 tools/report/review.py --run RUN_DIR [--out FILE]

Batch mode (called by `gdnav report` after report.py) writes to DIR (default BATCH_DIR/report):
  review.html              the batch: the paper-style tables (DIR/tables.md as gdnav report wrote it), across-run
                           mean +- std bands of the errors versus time, final-error scatter (click a point: that
                           run's page) and the list of runs (final errors from DIR/runs.csv)
  plotly-VERSION.js        plotly.js, one copy that every page of DIR loads
  review/run_NNNN.html     one page per complete run: true and estimated horizontal track, the errors versus time
                           (attitude, altitude, ground speed, horizontal) with the GNSS loss and the faults marked,
                           and the run's events (faults, GNSS fixes and GNSS-denied state, logged component events)
Run mode writes the page of one run folder (run.h5, metrics.yaml) to FILE (default RUN_DIR/review.html), with
plotly-VERSION.js beside it.

The run pages are written by --jobs worker processes (default: the CPUs this process may use); the batch page's
bands add the runs in run order whatever the number of workers, so the pages do not depend on it.
A page loads plotly.js from its report folder (review_page.py) and opens offline, from the folder it was written
in or from a copy of the whole folder. Needs Debian's python3-plotly, -numpy, -h5py, -yaml.
"""
import argparse
import multiprocessing
import os
import sys
import time

try:
    import plotly.graph_objects as go
    from plotly.subplots import make_subplots
except ImportError:
    print("review.py: python3-plotly is missing: install it (apt-get install python3-plotly) or use "
          "gdnav report --no-review", file=sys.stderr)
    sys.exit(1)

import numpy as np  # noqa: E402
import yaml  # noqa: E402

import run_events  # noqa: E402
from batch_runs import (DEG, DamagedRun, Streamed, batch_label, load_runs, read_runs_csv, read_table,  # noqa: E402
                        stopped_note)
from review_tables import fmt, run_summary_rows  # noqa: E402
from review_page import (PLOTLY_JS, Page, esc, markdown_html, rounded, stride_for,  # noqa: E402
                         write_plotly_js)

# Error rows of the run and batch pages: (title, [(column of /error, label, scale, decimals)], unit)
ERROR_ROWS = [
    ("attitude", [("yaw_rad", "ψ̂−ψ", DEG, 4), ("pitch_rad", "θ̂−θ", DEG, 4), ("bank_rad", "ξ̂−ξ", DEG, 4),
                  ("rot_rad", "‖Δr̂‖", DEG, 4)], "deg"),
    ("altitude", [("h_m", "ĥ−h", 1.0, 2)], "m"),
    ("ground speed", [("vn_mps", "v̂_N−v_N", 1.0, 3), ("ve_mps", "v̂_E−v_E", 1.0, 3)], "m/s"),
    ("horizontal", [("hor_m", "Δx_hor", 1.0, 2), ("cross_m", "Δx_cross", 1.0, 2), ("along_m", "Δx_along", 1.0, 2)],
     "m"),
]
ERROR_COLUMNS = [c[0] for _, cols, _ in ERROR_ROWS for c in cols]
TRACK_COLUMNS = ["north_m", "east_m"]
COLORS = ["#1f77b4", "#ff7f0e", "#2ca02c", "#d62728", "#9467bd"]


def fill(color, alpha=0.22):
    """A '#rrggbb' colour as a translucent rgba() for the band fills."""
    return f"rgba({int(color[1:3], 16)}, {int(color[3:5], 16)}, {int(color[5:7], 16)}, {alpha})"


def time_axis(fig, t_gnss, t_end):
    """The error plots' time axis spans the data from t = 0; a GNSS loss after the end is not drawn (it would stretch
    the axis past the data)."""
    if t_gnss <= t_end:
        fig.add_vline(x=t_gnss, line=dict(color="black", dash="dot", width=1.2), row="all", col=1)
        fig.add_annotation(x=t_gnss, y=1.0, yref="paper", xanchor="right", yanchor="bottom", showarrow=False,
                           yshift=22, text="GNSS lost", font=dict(size=11))
    fig.update_xaxes(range=[0.0, max(t_end, 1e-3)], row="all", col=1)


def error_figure(t, err, t_gnss, faults, t_end, t_stop=None):
    """Errors versus time, one row per group, GNSS loss and fault windows marked (and t_stop, the last step with
    every estimate, when an estimator stopped before the end)."""
    fig = make_subplots(rows=len(ERROR_ROWS), cols=1, shared_xaxes=True, vertical_spacing=0.04,
                        subplot_titles=[f"{title} error [{unit}]" for title, _, unit in ERROR_ROWS])
    keep = t >= 0.0  # the metrics window (t < 0 is the initial transient, docs/montecarlo.md)
    step = stride_for(int(keep.sum()))
    tt = rounded(t[keep][::step], 2)
    for row, (_, cols, unit) in enumerate(ERROR_ROWS, start=1):
        for k, (col, label, scale, dec) in enumerate(cols):
            fig.add_trace(go.Scatter(x=tt, y=rounded(err[col][keep][::step] * scale, dec), name=f"{label} [{unit}]",
                                     mode="lines", line=dict(width=1.2, color=COLORS[k % len(COLORS)]),
                                     legendgroup=str(row)), row=row, col=1)
    for f in faults:
        a, b = float(f.get("at_s", 0.0)), float(f.get("until_s", t_end))
        fig.add_vrect(x0=a, x1=b, fillcolor="orange", opacity=0.18, line_width=0, row="all", col=1)
        fig.add_annotation(x=a, y=1.0, yref="paper", xanchor="left", yanchor="bottom", showarrow=False, yshift=22,
                           text="fault: " + esc(run_events.fault_label(f)), font=dict(size=10, color="#b35900"))
    if t_stop is not None:
        fig.add_vline(x=t_stop, line=dict(color="#d62728", dash="dash", width=1.2), row="all", col=1)
        fig.add_annotation(x=t_stop, y=1.0, yref="paper", xanchor="right", yanchor="bottom", showarrow=False,
                           yshift=4, text=f"estimates stop (t = {t_stop:.2f} s)", font=dict(size=11, color="#d62728"))
    time_axis(fig, t_gnss, t_end)
    fig.update_xaxes(title_text="t [s]", row=len(ERROR_ROWS), col=1)
    fig.update_layout(height=230 * len(ERROR_ROWS) + 80, margin=dict(l=60, r=20, t=80, b=40),
                      legend=dict(orientation="h", y=-0.06), hovermode="x unified")
    return fig


def track_figure(truth, est, t_gnss):
    """Horizontal track (north/east from the initial true position), true and estimated, GNSS loss and ends marked."""
    fig = go.Figure()
    step = stride_for(len((truth or est)["t"]))
    for name, d, color in (("true", truth, "black"), ("estimated", est, "#d62728")):
        if d is None:  # no reference trajectory
            continue
        east, north = d["east_m"][::step] / 1000.0, d["north_m"][::step] / 1000.0
        fig.add_trace(go.Scatter(x=rounded(east, 4), y=rounded(north, 4), mode="lines", name=f"{name} track",
                                 line=dict(color=color, width=1.5), text=rounded(d["t"][::step], 1),
                                 hovertemplate="t = %{text} s<br>E %{x} km, N %{y} km"))
        i = int(np.searchsorted(d["t"], t_gnss))
        finite = np.flatnonzero(np.isfinite(d["east_m"]))  # an estimator that stopped ends its track early
        last = int(finite[-1]) if len(finite) else -1
        for j, what, symbol in ((i, f"{name}: GNSS lost (t = {t_gnss:g} s)", "x"), (last, f"{name}: end", "circle")):
            if 0 <= j < len(d["t"]):
                fig.add_trace(go.Scatter(x=[float(d["east_m"][j]) / 1000.0], y=[float(d["north_m"][j]) / 1000.0],
                                         mode="markers", name=what, marker=dict(color=color, symbol=symbol, size=10)))
    fig.update_layout(title="Horizontal track (from the initial true position)", height=620,
                      xaxis_title="east [km]", yaxis_title="north [km]", margin=dict(l=60, r=20, t=50, b=40))
    fig.update_yaxes(scaleanchor="x", scaleratio=1)
    return fig


def events_figure(t_fix, denied, faults, timed, t_start, t_end):
    """Timeline: GNSS fixes, navigation GNSS-denied, each fault, each component's logged events."""
    fig = go.Figure()
    if len(t_fix):
        fig.add_trace(go.Scatter(x=rounded(t_fix, 2), y=["GNSS fixes"] * len(t_fix), mode="markers", name="GNSS fix",
                                 marker=dict(symbol="line-ns-open", size=10, color="#2ca02c")))
    for a, b in denied:
        fig.add_trace(go.Scatter(x=[a, b], y=["navigation: GNSS-denied"] * 2, mode="lines", showlegend=False,
                                 line=dict(color="#d62728", width=10), hovertemplate="GNSS-denied %{x} s"))
    for f in faults:
        a, b = float(f.get("at_s", 0.0)), float(f.get("until_s", t_end))
        lab = f"fault: {f.get('kind', '?')} {f.get('target', '?')}"
        fig.add_trace(go.Scatter(x=[a, b], y=[lab, lab], mode="lines", showlegend=False, line=dict(color="orange",
                                 width=10), hovertemplate=esc(run_events.fault_label(f)) + " %{x} s"))
    by_comp = {}
    for t, comp, level, msg in timed:
        by_comp.setdefault(comp, []).append((t, f"{esc(level)}: {esc(msg)}"))
    for comp, ev in sorted(by_comp.items()):
        fig.add_trace(go.Scatter(x=[e[0] for e in ev], y=[f"log: {comp}"] * len(ev), mode="markers", name=comp,
                                 marker=dict(size=8, symbol="diamond"), text=[e[1] for e in ev],
                                 hovertemplate="t = %{x} s<br>%{text}<extra></extra>", showlegend=False))
    rows = 1 + bool(denied) + len(faults) + len(by_comp)
    fig.update_layout(title="Sensor and fault events", height=120 + 36 * rows, margin=dict(l=200, r=20, t=50, b=40),
                      xaxis=dict(title="t [s]", range=[t_start, t_end]), showlegend=False)
    return fig


def run_page(run_dir, h5, metrics, path, title, back=None, lib_dir=None):
    """Write the review page of one run (plotly.js from LIB_DIR, default the page's folder: review_page.Page.write);
    returns (t, error columns) of its /error table for the batch bands."""
    t, err, t_gnss = read_table(h5, "error", ERROR_COLUMNS)
    tt, tru, _ = read_table(h5, "truth", TRACK_COLUMNS)
    te, est, _ = read_table(h5, "estimate", TRACK_COLUMNS + ["gnss_denied"])
    tf, _, _ = read_table(h5, "gnss", [])
    truth, estimate = dict(tru, t=tt), dict(est, t=te)
    faults, fault_src = run_events.faults(run_dir)
    timed, untimed = run_events.log_events(run_dir)
    denied = run_events.intervals(te, est["gnss_denied"])
    t_end = float(t[-1]) if len(t) else 0.0

    page = Page(title)
    page.add(f"<h1>{esc(title)}</h1>")
    if back:
        page.add(f'<p><a href="{esc(back)}">back to the batch</a></p>')
    t_track = (float(tt[0]), float(tt[-1])) if len(tt) else (0.0, 0.0)
    gnss = f"GNSS lost at t = {t_gnss:g} s" if t_gnss <= t_end else f"GNSS not lost before the end (t = {t_end:g} s)"
    page.note(f"{os.path.realpath(run_dir)} · {gnss} · errors = estimate − truth (docs/montecarlo.md); "
              f"track from t = {t_track[0]:g} s to {t_track[1]:g} s, errors from t = 0 (the metrics window), "
              "at most 4000 points per curve.")
    page.table(["metric (metrics.yaml)", "value"], run_summary_rows(metrics))
    referenced = metrics.get("reference") != "none"
    page.heading("Track")
    page.figure(track_figure(truth if referenced else None, estimate, t_gnss), "track")
    page.heading("Errors versus time")
    if referenced:
        t_stop = float(metrics["t_end_s"]) if stopped_note(metrics) else None
        page.figure(error_figure(t, err, t_gnss, faults, t_end, t_stop), "errors")
    else:
        page.note("No reference trajectory (metrics.yaml reference: none): the run has no errors to plot.")
    page.heading("Events")
    page.figure(events_figure(tf, denied, faults, timed, float(tt[0]) if len(tt) else 0.0, t_end), "events")
    rows = [(fmt(float(f.get("at_s", 0.0)), 2), f"fault ({fault_src})",
             run_events.fault_label(f) + (f", until {f['until_s']} s" if "until_s" in f else ", to the end"))
            for f in faults]
    rows += [(fmt(a, 2), "navigation", f"GNSS-denied until {b:.2f} s") for a, b in denied]
    if len(tf):
        rows.append((fmt(float(tf[-1]), 2), "GNSS receiver", f"last of {len(tf)} fixes"))
    rows += [(fmt(t_ev, 2), f"log: {comp}", f"{level}: {msg}") for t_ev, comp, level, msg in timed]
    rows.sort(key=lambda r: float(r[0]) if r[0] != "n/a" else float("inf"))
    rows += [("—", "log", f"{level}: {msg}") for level, msg in untimed]
    rows += [("—", "clock", note) for note in run_events.clock_notes(run_dir)]
    page.table(["t [s]", "source", "event"], rows, right={0})
    page.write(path, lib_dir)
    return t, err


def band_figure(stats, t_gnss):
    fig = make_subplots(rows=len(ERROR_ROWS), cols=1, shared_xaxes=True, vertical_spacing=0.04,
                        subplot_titles=[f"{title} error [{unit}]: mean ± σ across runs"
                                        for title, _, unit in ERROR_ROWS])
    keep = stats.t >= 0.0
    step = stride_for(int(keep.sum()))
    tt = rounded(stats.t[keep][::step], 2)
    t_end = float(stats.t[-1]) if len(stats.t) else 0.0
    for row, (_, cols, unit) in enumerate(ERROR_ROWS, start=1):
        for k, (col, label, scale, dec) in enumerate(cols):
            mean, std = stats.mean_std(col)
            mean, std = mean[keep][::step] * scale, std[keep][::step] * scale
            color = COLORS[k % len(COLORS)]
            fig.add_trace(go.Scatter(x=tt, y=rounded(mean + std, dec), mode="lines", line=dict(width=0, color=color),
                                     showlegend=False, hoverinfo="skip", legendgroup=col), row=row, col=1)
            fig.add_trace(go.Scatter(x=tt, y=rounded(mean - std, dec), mode="lines", line=dict(width=0, color=color),
                                     fill="tonexty", fillcolor=fill(color), name=f"{label} ± σ", legendgroup=col,
                                     hoverinfo="skip"), row=row, col=1)
            fig.add_trace(go.Scatter(x=tt, y=rounded(mean, dec), mode="lines", line=dict(width=1.4, color=color),
                                     name=f"{label} mean [{unit}]", legendgroup=col), row=row, col=1)
    time_axis(fig, t_gnss, t_end)
    fig.update_xaxes(title_text="t [s]", row=len(ERROR_ROWS), col=1)
    fig.update_layout(height=230 * len(ERROR_ROWS) + 80, margin=dict(l=60, r=20, t=80, b=40),
                      legend=dict(orientation="h", y=-0.06))
    return fig


def scatter_figure(csv_rows, pages):
    """Final cross/along-track error and final horizontal error versus distance; each point opens its run page."""
    idx = [i for i in sorted(csv_rows) if i in pages]
    r = [csv_rows[i] for i in idx]
    links = [pages[i] for i in idx]
    text = [f"run {i}" for i in idx]
    fig = make_subplots(rows=1, cols=2, horizontal_spacing=0.1,
                        subplot_titles=["final cross- and along-track error [m]",
                                        "final horizontal error versus distance since t_GNSS"])
    hover = "%{text}: (%{x}, %{y})<br>click: open the run's page<extra></extra>"
    fig.add_trace(go.Scatter(x=[v["cross_m_final"] for v in r], y=[v["along_m_final"] for v in r], mode="markers",
                             text=text, customdata=links, hovertemplate=hover, marker=dict(size=10, color="#9467bd"),
                             name="runs"), row=1, col=1)
    fig.add_trace(go.Scatter(x=[v["distance"] / 1000.0 for v in r], y=[v["hor_m_final"] for v in r],
                             mode="markers", text=[f"{s}, {v['hor_pct']:.2f} %" for s, v in zip(text, r)],
                             customdata=links, hovertemplate=hover, marker=dict(size=10, color="#ff7f0e"),
                             name="runs "), row=1, col=2)
    fig.update_xaxes(title_text="cross-track [m] (> 0: right of track)", zeroline=True, row=1, col=1)
    fig.update_yaxes(title_text="along-track [m] (> 0: ahead)", zeroline=True, row=1, col=1)
    fig.update_xaxes(title_text="distance [km]", row=1, col=2)
    fig.update_yaxes(title_text="final Δx_hor [m]", rangemode="tozero", row=1, col=2)
    fig.update_layout(height=480, showlegend=False, margin=dict(l=60, r=20, t=50, b=50))
    return fig


class Progress:
    """One line per run page when the batch is small, else every 5 s (and the last)."""

    def __init__(self, total):
        self.total, self.last, self.t0 = total, 0.0, time.monotonic()

    def done(self, k, name):
        now = time.monotonic()
        if self.total <= 10 or k == self.total or now - self.last >= 5.0:
            self.last = now
            print(f"review.py: run page {k}/{self.total} ({name}), {now - self.t0:.0f} s", flush=True)


def _run_page_job(job):
    """One run page in a worker process (batch_pages): returns what the batch bands need."""
    r, path, title, lib_dir = job
    return run_page(r["dir"], r["h5"], r["metrics"], path, title, back="../review.html", lib_dir=lib_dir)


def batch_pages(batch, out, tables_md, runs_csv, jobs=1):
    try:
        runs = load_runs(batch)
    except DamagedRun as e:
        print(f"review.py: {e}", file=sys.stderr)
        return 1
    if not runs:
        print(f"review.py: no complete run in {batch}/runs", file=sys.stderr)
        return 1
    if not os.path.isfile(runs_csv):
        print(f"review.py: {runs_csv} not found (gdnav report writes it before calling review.py)", file=sys.stderr)
        return 1
    label = batch_label(batch)
    os.makedirs(os.path.join(out, "review"), exist_ok=True)
    stats, pages, t_gnss = Streamed(ERROR_COLUMNS), {}, 100.0
    progress = Progress(len(runs))
    rels = [f"review/{os.path.basename(r['dir'])}.html" for r in runs]
    write_plotly_js(out)  # once, before the workers: every page of the report loads this one copy
    work = [(r, os.path.join(out, rel), f"Run {r['index']} — {label}, seed {r['metrics'].get('seed')}", out)
            for r, rel in zip(runs, rels)]
    jobs = max(1, min(jobs, len(runs)))
    pool = multiprocessing.get_context("fork").Pool(jobs) if jobs > 1 else None
    try:
        # imap keeps the run order: the bands are summed in the same order with any number of workers.
        results = pool.imap(_run_page_job, work) if pool else map(_run_page_job, work)
        for k, (r, rel, (t, err)) in enumerate(zip(runs, rels, results), start=1):
            t_gnss = float(r["metrics"].get("t_gnss_s", t_gnss))
            stats.add(t, err)
            pages[r["index"]] = rel
            progress.done(k, os.path.basename(r["dir"]))
    finally:
        if pool:
            pool.close()
            pool.join()

    csv_rows = read_runs_csv(runs_csv)
    page = Page(f"Flight review — {label}")
    page.add(f"<h1>Flight review — {esc(label)}, {len(runs)} runs</h1>")
    page.note(f"{batch} · the tables are gdnav report's ({os.path.basename(tables_md)}); bands: across-run mean ± σ "
              "(population) of each error at each time; click a point of the scatter to open that run's page.")
    if os.path.isfile(tables_md):
        with open(tables_md, encoding="utf-8") as f:
            page.add(markdown_html(f.read()))
    page.heading("Errors versus time across runs")
    page.figure(band_figure(stats, t_gnss), "bands")
    page.heading("Final errors per run")
    page.figure(scatter_figure(csv_rows, pages), "final")
    page.heading("Runs")
    rows = []
    for i in sorted(pages):
        v = csv_rows.get(i, {})
        stop = "" if v.get("estimates_complete", 1.0) == 1.0 else f" (estimates stop at t = {v.get('t_end_s'):.2f} s)"
        rows.append([("html", f'<a href="{esc(pages[i])}">run {i}</a>{esc(stop)}'), fmt(v.get("hor_m_final"), 1),
                     fmt(v.get("hor_pct"), 2), fmt(v.get("distance"), 0),
                     fmt(v.get("h_m_final"), 2, True), fmt((v.get("rot_rad_mean") or float("nan")) * DEG, 3)])
    page.table(["run", "final Δx_hor [m]", "[%]", "distance [m]", "final ĥ−h [m]", "‖Δr̂‖ mean [deg]"], rows)
    if any(v.get("estimates_complete", 1.0) != 1.0 for v in csv_rows.values()):
        page.note("final: at t_end, the end of the flight or, for a run whose estimator stopped, its last step with "
                  "every estimate; distance: flown since t_GNSS up to t_end.")
    page.write(os.path.join(out, "review.html"))
    size = sum(os.path.getsize(os.path.join(out, p)) for p in list(pages.values()) + ["review.html", PLOTLY_JS])
    print(f"review.py: {len(runs)} runs -> {os.path.join(out, 'review.html')}, review/run_*.html and {PLOTLY_JS} "
          f"({size / 1e6:.1f} MB in all)", flush=True)
    return 0


def main():
    p = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    p.add_argument("batch", nargs="?")
    p.add_argument("--run", help="one run folder (run.h5, metrics.yaml) instead of a batch")
    p.add_argument("--out", default=None)
    p.add_argument("--tables", default=None, help="tables.md of gdnav report (default OUT/tables.md)")
    p.add_argument("--runs-csv", default=None, help="runs.csv of gdnav report (default OUT/runs.csv)")
    p.add_argument("--jobs", type=int, default=len(os.sched_getaffinity(0)),
                   help="run pages written in parallel (default: the CPUs this process may use)")
    a = p.parse_args()
    if a.jobs < 1:
        p.error(f"--jobs must be at least 1 (got {a.jobs})")
    if a.run:
        with open(os.path.join(a.run, "metrics.yaml")) as f:
            m = yaml.safe_load(f)
        out = a.out or os.path.join(a.run, "review.html")
        run_page(a.run, os.path.join(a.run, "run.h5"), m, out, f"Run {m.get('run_index')}, seed {m.get('seed')}")
        print(f"review.py: {out}")
        return 0
    if not a.batch:
        p.error("give BATCH_DIR or --run RUN_DIR")
    out = a.out or os.path.join(a.batch, "report")
    return batch_pages(a.batch, out, a.tables or os.path.join(out, "tables.md"),
                       a.runs_csv or os.path.join(out, "runs.csv"), a.jobs)


def main_one_line():
    """main(), with a file the operating system refused (a full disk) as one line and exit code 6, as gdnav's own
    writers (docs/runtime.md, "Exit codes")."""
    try:
        return main()
    except OSError as e:
        print(f"review.py: {e.filename}: {e.strerror}" if e.filename else f"review.py: {e}",
              file=sys.stderr)
        return 6


if __name__ == "__main__":
    sys.exit(main_one_line())
