"""The HTML page of gdnav compare (compare.py --out DIR): DIR/compare.html with PNG figures beside it.

  compare.html          the tables of compare.py, the figures and, per run, links to each batch's run page
  paired_<metric>.png   a paired scatter per metric: base value against candidate value, one point a run (one
                        colour per candidate); below the diagonal the candidate is better. Each point is an area of
                        the page's image map linking to the candidate's review page of that run
  bands.png             across-run mean +- sigma (population) of the errors versus time, every batch on the runs
                        they all completed (run.h5 /error, as gdnav report's figures)
  review/LABEL/run_NNNN.html   a run's review page (review.py), written only for runs whose batch has none
                        (BATCH/report/review/run_NNNN.html, made by gdnav report)
Needs Debian's python3-matplotlib, -numpy, -h5py and -plotly (run pages).
"""
import math
import multiprocessing
import os
import re

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
import matplotlib.ticker  # noqa: E402
import numpy as np  # noqa: E402

from batch_runs import DEG, Streamed, read_table  # noqa: E402
from review_page import _STYLE, esc, markdown_html  # noqa: E402

COLORS = ["tab:orange", "tab:green", "tab:red", "tab:purple", "tab:brown", "tab:pink"]
BASE_COLOR = "tab:blue"
# Rows of bands.png: column of /error, label, scale, unit.
BAND_ROWS = [("rot_rad", r"$\|\Delta\hat r\|$", DEG, "deg"), ("h_m", r"$\hat h-h$", 1.0, "m"),
             ("vn_mps", r"$\hat v_N-v_N$", 1.0, "m/s"), ("ve_mps", r"$\hat v_E-v_E$", 1.0, "m/s"),
             ("hor_m", r"$\Delta\hat x_{hor}$", 1.0, "m")]
DPI = 100


def safe(label):
    return re.sub(r"[^A-Za-z0-9_.-]+", "_", label).strip("_") or "batch"


def _run_page_job(job):
    import review  # plotly: only in the workers that write run pages
    run_dir, path, title, lib_dir = job
    review.run_page(run_dir, os.path.join(run_dir, "run.h5"), review_metrics(run_dir), path, title, lib_dir=lib_dir)
    return path


def review_metrics(run_dir):
    import yaml
    with open(os.path.join(run_dir, "metrics.yaml")) as fh:
        return yaml.safe_load(fh)


def run_pages(out, batches, runs, make_pages):
    """{(batch label, run index): address of its review page relative to OUT}: gdnav report's page where there is
    one, else a page written here (or, without make_pages, the run folder)."""
    links, work = {}, []
    for b in batches:
        for i in (i for i in runs if i in b.runs):
            d = b.dirs[i]
            existing = os.path.join(b.path, "report", "review", os.path.basename(d) + ".html")
            if os.path.isfile(existing):
                links[(b.label, i)] = os.path.relpath(existing, out)
            elif make_pages:
                rel = os.path.join("review", safe(b.label), os.path.basename(d) + ".html")
                os.makedirs(os.path.dirname(os.path.join(out, rel)), exist_ok=True)
                work.append((d, os.path.join(out, rel), f"Run {i} — {b.label}, seed {b.runs[i].get('seed')}", out))
                links[(b.label, i)] = rel
            else:
                links[(b.label, i)] = os.path.relpath(d, out)
    if work:
        import review_page  # plotly.js written once, before the workers: every page here loads this copy
        review_page.write_plotly_js(out)
        jobs = max(1, min(len(work), len(os.sched_getaffinity(0))))
        with multiprocessing.get_context("fork").Pool(jobs) as pool:
            list(pool.imap(_run_page_job, work))
    return links, len(work)


def scatter(out, key, label, unit, base, pairs, value, links):
    """paired_KEY.png and the <area> elements of its image map."""
    fig, ax = plt.subplots(figsize=(4.6, 4.4), dpi=DPI)
    pts, lo, hi = [], math.inf, -math.inf
    for k, (cand, runs) in enumerate(pairs):
        xy = [(i, value(base.runs[i]), value(cand.runs[i])) for i in runs]
        xy = [(i, x, y) for i, x, y in xy if math.isfinite(x) and math.isfinite(y)]
        if not xy:
            continue
        xs, ys = [p[1] for p in xy], [p[2] for p in xy]
        ax.scatter(xs, ys, s=18, color=COLORS[k % len(COLORS)], label=cand.label, zorder=3)
        lo, hi = min(lo, *xs, *ys), max(hi, *xs, *ys)
        pts += [(cand, i, x, y) for i, x, y in xy]
    if not pts:
        ax.text(0.5, 0.5, "n/a: no run has this metric\nin both batches", ha="center", va="center",
                transform=ax.transAxes)
    else:
        pad = (hi - lo) * 0.08 or abs(hi) * 0.1 or 1.0
        lo, hi = lo - pad, hi + pad
        ax.plot([lo, hi], [lo, hi], color="k", lw=0.7, ls="--", zorder=1)
        ax.set_xlim(lo, hi)
        ax.set_ylim(lo, hi)
        ax.set_aspect("equal")
        ax.xaxis.set_major_locator(matplotlib.ticker.MaxNLocator(5))
        ax.yaxis.set_major_locator(matplotlib.ticker.MaxNLocator(6))
        ax.legend(fontsize=7, loc="upper left", title="candidate", title_fontsize=7)
    ax.set_xlabel(f"{base.label} [{unit}]")
    ax.set_ylabel(f"candidate [{unit}]")
    ax.set_title(f"{label} [{unit}], per run\n(below the dashed line: candidate better)", fontsize=9)
    ax.grid(True, alpha=0.3)
    fig.tight_layout()
    fig.canvas.draw()
    height = fig.get_size_inches()[1] * DPI
    areas = []
    for cand, i, x, y in pts:
        px, py = ax.transData.transform((x, y))
        href = links.get((cand.label, i), "")
        areas.append(f'<area shape="circle" coords="{px:.0f},{height - py:.0f},6" href="{esc(href)}" '
                     f'title="run {i}: {esc(base.label)} {x:.4g}, {esc(cand.label)} {y:.4g}" '
                     f'alt="run {i}">')
    name = f"paired_{key}.png"
    fig.savefig(os.path.join(out, name), dpi=DPI)
    plt.close(fig)
    return name, areas


def bands(out, batches, runs):
    """bands.png: every batch's mean +- sigma over RUNS of the errors versus time."""
    cols = [r[0] for r in BAND_ROWS]
    fig, axes = plt.subplots(len(BAND_ROWS), 1, figsize=(9.5, 2.0 * len(BAND_ROWS) + 0.8), dpi=DPI, sharex=True)
    t_gnss, t_max = None, -math.inf
    for k, b in enumerate(batches):
        stats = Streamed(cols)
        for i in runs:
            t, err, tg = read_table(os.path.join(b.dirs[i], "run.h5"), "error", cols)
            stats.add(t, err)
            t_gnss, t_max = tg, max(t_max, float(t[-1]) if len(t) else t_max)
        color = BASE_COLOR if k == 0 else COLORS[(k - 1) % len(COLORS)]
        for ax, (col, label, scale, unit) in zip(axes, BAND_ROWS):
            mean, std = stats.mean_std(col)
            ax.fill_between(stats.t, (mean - std) * scale, (mean + std) * scale, color=color, alpha=0.2, lw=0)
            # The base thick under the candidates, so that it shows where they coincide.
            ax.plot(stats.t, mean * scale, color=color, lw=2.4 if k == 0 else 1.0, zorder=2 + k,
                    label=f"{b.label}: mean ± σ")
            ax.set_ylabel(f"{label} [{unit}]")
    for ax in axes:
        ax.grid(True, alpha=0.3)
        if t_gnss is not None and np.isfinite(t_gnss) and t_gnss <= t_max:
            ax.axvline(t_gnss, color="k", ls=":", lw=0.8)
    axes[0].legend(fontsize=8, loc="upper left")
    n = f"{len(runs)} run" + ("s" if len(runs) != 1 else "")
    axes[0].set_title(f"Errors versus time: across-run mean ± σ over the same {n} of every batch", fontsize=10)
    axes[-1].set_xlabel("t [s]   (dotted: GNSS lost)" if t_gnss is not None and t_gnss <= t_max
                        else "t [s]   (GNSS not lost before the end)")
    fig.tight_layout()
    fig.savefig(os.path.join(out, "bands.png"), dpi=DPI)
    plt.close(fig)
    return "bands.png"


def runs_table(batches, runs, links):
    head = "<tr><th>run</th>" + "".join(f"<th>{esc(b.label)}</th>" for b in batches) + "</tr>"
    rows = "".join(f"<tr><td>run {i}</td>" + "".join(
        f'<td><a href="{esc(links[(b.label, i)])}">review page</a></td>' if (b.label, i) in links else "<td>—</td>"
        for b in batches) + "</tr>" for i in runs)
    return f"<table>{head}{rows}</table>"


def write(out, batches, pairs, paired, common, text, make_pages=True):
    """Writes OUT/compare.html and its figures; returns the page's path."""
    os.makedirs(out, exist_ok=True)
    base = batches[0]
    every = sorted(set().union(*(set(r) for _, r in pairs)))
    links, made = run_pages(out, batches, every, make_pages)
    parts = [markdown_html(text), "<h2>Paired runs</h2>",
             '<p class="note">One point per run: its value in the base batch (x) against the candidate (y). Click a '
             "point to open that run's review page in the candidate batch.</p>", "<div>"]
    maps = []
    for key, label, unit, value, _ in paired:
        name, areas = scatter(out, key, label.replace("\\|", "|"), unit, base, pairs, value, links)
        parts.append(f'<img src="{name}" usemap="#map_{key}" alt="{esc(label)}" style="margin:4px">')
        maps.append(f'<map name="map_{key}">' + "".join(areas) + "</map>")
    parts += ["</div>"] + maps
    if common:
        parts += ["<h2>Errors versus time</h2>", f'<img src="{bands(out, batches, common)}" alt="error bands">']
    parts += ["<h2>Runs</h2>", '<p class="note">Review pages: gdnav report\'s where the batch has them, else '
              f"written here ({made} pages).</p>", runs_table(batches, every, links)]
    path = os.path.join(out, "compare.html")
    with open(path, "w", encoding="utf-8") as fh:
        fh.write(f'<!DOCTYPE html>\n<html lang="en"><head><meta charset="utf-8"><title>gdnav compare: '
                 f"{esc(', '.join(b.label for b in batches))}</title><style>{_STYLE}</style></head>\n<body>\n"
                 + "\n".join(parts) + "\n</body></html>\n")
    return path
