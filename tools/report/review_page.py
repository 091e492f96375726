"""HTML pages of plotly figures, for review.py (gdnav's flight review pages).

A page opens offline. plotly.js (Debian's python3-plotly bundle, 8.7 MB of unminified text) is not in the page: it is
written once per report folder, gzip-compressed and base64-encoded (2.5 MB) as plotly-VERSION.packed.js, beside the
pages or in a folder above them (the caller names it); each page loads it with a relative <script src> and unpacks it
with DecompressionStream (Chrome 80, Firefox 113, Safari 16.4 and later), so a 100-run report holds one copy instead
of a hundred. Each figure is a JSON block, gzip-compressed and base64-encoded the same way, that the page draws once
plotly.js is loaded; a point whose customdata is a page address (".html") opens that page when clicked.
"""
import base64
import functools
import gzip
import html
import json
import os

import numpy as np
import plotly
from plotly.offline import get_plotlyjs

from file_errors import naming

_STYLE = """
body { font-family: system-ui, sans-serif; margin: 1.2em 2em; color: #222; max-width: 1400px; }
h1 { font-size: 1.5em; } h2 { font-size: 1.2em; margin-top: 1.6em; border-bottom: 1px solid #ccc; }
h3 { font-size: 1.0em; margin-top: 1.2em; }
table { border-collapse: collapse; margin: 0.5em 0; font-size: 0.85em; }
th, td { border: 1px solid #ccc; padding: 2px 7px; } th { background: #f2f2f2; }
td.r { text-align: right; font-variant-numeric: tabular-nums; }
.plot { width: 100%; } .note { color: #555; font-size: 0.85em; }
#loading { color: #a00; }
"""

# Unpacks plotly.js (from the shared file) and each figure, draws them, then marks the body (data-plots-ready =
# number of figures drawn).
_SCRIPT = """
(async function () {
  const status = document.getElementById('loading');
  if (typeof DecompressionStream === 'undefined') {
    status.textContent = 'This browser cannot unpack plotly.js and the figures (DecompressionStream is missing).';
    return;
  }
  if (typeof window.gdnavPlotlyPacked !== 'string') {
    status.textContent = 'plotly.js did not load: ' + document.getElementById('plotly-js').getAttribute('src') +
      ' is missing (it is written once per report folder, beside or above the pages).';
    return;
  }
  async function unpack(b64) {
    const raw = atob(b64);
    const bytes = new Uint8Array(raw.length);
    for (let i = 0; i < raw.length; ++i) bytes[i] = raw.charCodeAt(i);
    return new Response(new Blob([bytes]).stream().pipeThrough(new DecompressionStream('gzip'))).text();
  }
  (0, eval)(await unpack(window.gdnavPlotlyPacked));
  const divs = document.querySelectorAll('div.plot');
  for (const div of divs) {
    const spec = JSON.parse(await unpack(document.getElementById(div.id + '-data').textContent));
    for (const trace of spec.data)  // arrays written once per figure (Page.figure)
      for (const key of Object.keys(trace))
        if (trace[key] !== null && typeof trace[key] === 'object' && 'gdnavShared' in trace[key])
          trace[key] = spec.gdnavShared[trace[key].gdnavShared];
    await Plotly.newPlot(div, spec.data, spec.layout, {responsive: true, displaylogo: false});
    div.on('plotly_click', function (ev) {
      const p = ev && ev.points && ev.points[0];
      if (p && typeof p.customdata === 'string' && p.customdata.endsWith('.html')) window.location.href = p.customdata;
    });
  }
  status.remove();
  document.body.dataset.plotsReady = String(divs.length);
})();
"""

PLOTLY_JS = f"plotly-{plotly.__version__}.packed.js"


def packed(text):
    """TEXT gzip-compressed (level 9, no time stamp: the same bytes every time) and base64-encoded."""
    return base64.b64encode(gzip.compress(text.encode("utf-8"), compresslevel=9, mtime=0)).decode("ascii")


@functools.lru_cache(maxsize=1)
def plotly_js_file():
    """The bytes of plotly-VERSION.packed.js (computed once per process; forked workers inherit it)."""
    return (f"// plotly.js {plotly.__version__} (MIT licence, Debian's python3-plotly bundle), gzip-compressed and "
            f"base64-encoded: gdnav's review pages unpack it.\nwindow.gdnavPlotlyPacked = "
            f'"{packed(get_plotlyjs())}";\n').encode("ascii")


def write_plotly_js(folder):
    """FOLDER/plotly-VERSION.packed.js, written once: kept when already there with the right size. Written under a
    temporary name and renamed, so worker processes writing pages at the same time never see half a file."""
    path = os.path.join(folder, PLOTLY_JS)
    code = plotly_js_file()
    if os.path.isfile(path) and os.path.getsize(path) == len(code):
        return path
    os.makedirs(folder, exist_ok=True)
    tmp = f"{path}.{os.getpid()}.tmp"
    with naming(path), open(tmp, "wb") as f:
        f.write(code)
    os.replace(tmp, path)
    return path


def rounded(x, decimals):
    """An array as a list of floats rounded to DECIMALS places (NaN kept: drawn as a gap)."""
    return np.round(np.asarray(x, dtype=float), decimals).tolist()


def stride_for(n, max_points=4000):
    """Row step so that a trace of N samples has at most MAX_POINTS points."""
    return max(1, -(-n // max_points))


def esc(text):
    return html.escape(str(text), quote=True)


class Page:
    """An HTML page: headings, paragraphs, tables and plotly figures, written as one file."""

    def __init__(self, title):
        self.title = title
        self.parts = []
        self.figures = 0

    def add(self, fragment):
        self.parts.append(fragment)

    def heading(self, text, level=2):
        self.add(f"<h{level}>{esc(text)}</h{level}>")

    def note(self, text):
        self.add(f'<p class="note">{esc(text)}</p>')

    def table(self, header, rows, right=None):
        """HEADER: cell texts; ROWS: lists of cells, each a text or ('html', markup); RIGHT: right-aligned columns."""
        right = set(range(1, len(header))) if right is None else set(right)
        out = ["<table><tr>" + "".join(f"<th>{esc(h)}</th>" for h in header) + "</tr>"]
        for row in rows:
            cells = []
            for i, c in enumerate(row):
                body = c[1] if isinstance(c, tuple) else esc(c)
                cells.append(f'<td class="r">{body}</td>' if i in right else f"<td>{body}</td>")
            out.append("<tr>" + "".join(cells) + "</tr>")
        self.add("".join(out) + "</table>")

    def figure(self, fig, name):
        """A plotly figure (graph_objects.Figure) drawn in a div with id NAME."""
        spec = json.loads(json.dumps(fig.to_plotly_json(), cls=plotly.utils.PlotlyJSONEncoder))
        # An array that several traces share (the time axis of ten error curves) is written once: the page puts it
        # back into each trace before drawing, so the figure is the one given.
        shared, where = [], {}
        for trace in spec["data"]:
            for key in ("x", "y", "customdata"):
                value = trace.get(key)
                if not isinstance(value, list) or len(value) < 100:
                    continue
                text = json.dumps(value, separators=(",", ":"))
                if text not in where:
                    where[text] = len(shared)
                    shared.append(value)
                trace[key] = {"gdnavShared": where[text]}
        spec["gdnavShared"] = shared
        spec = json.dumps(spec, separators=(",", ":"))
        self.add(f'<div class="plot" id="{esc(name)}"></div>'
                 f'<script type="application/octet-stream" id="{esc(name)}-data">{packed(spec)}</script>')
        self.figures += 1

    def write(self, path, lib_dir=None):
        """Writes the page to PATH; plotly.js is loaded from LIB_DIR (default: the page's folder), written there once
        (write_plotly_js)."""
        lib = write_plotly_js(lib_dir if lib_dir is not None else os.path.dirname(os.path.abspath(path)))
        src = os.path.relpath(lib, os.path.dirname(os.path.abspath(path))).replace(os.sep, "/")
        with naming(path), open(path, "w", encoding="utf-8") as f:
            f.write(f'<!DOCTYPE html>\n<html lang="en"><head><meta charset="utf-8"><title>{esc(self.title)}</title>'
                    f"<style>{_STYLE}</style></head>\n<body>\n"
                    f'<p id="loading">Loading the plots (plotly.js from {esc(src)})...</p>\n')
            for p in self.parts:
                f.write(p + "\n")
            f.write(f'<script id="plotly-js" src="{esc(src)}"></script>\n<script>{_SCRIPT}</script>\n</body></html>\n')


def markdown_html(text):
    """The Markdown gdnav report writes (tables.md: headings, bullet lines, paragraphs, pipe tables) as HTML."""
    out, table, bullets = [], [], []

    def cells(line):
        parts, cur, i = [], "", 0
        body = line.strip()[1:-1] if line.strip().endswith("|") else line.strip()[1:]
        while i < len(body):
            if body[i] == "\\" and i + 1 < len(body) and body[i + 1] == "|":
                cur += "|"
                i += 2
                continue
            if body[i] == "|":
                parts.append(cur.strip())
                cur = ""
            else:
                cur += body[i]
            i += 1
        parts.append(cur.strip())
        return parts

    def flush():
        if bullets:
            out.append("<ul>" + "".join(f"<li>{esc(b)}</li>" for b in bullets) + "</ul>")
            bullets.clear()
        if table:
            head, rows = cells(table[0]), [cells(r) for r in table[2:]]
            align = [c.endswith(":") for c in cells(table[1])] if len(table) > 1 else []
            h = "<tr>" + "".join(f"<th>{esc(c)}</th>" for c in head) + "</tr>"
            b = "".join("<tr>" + "".join(f'<td class="r">{esc(c)}</td>' if i < len(align) and align[i]
                                         else f"<td>{esc(c)}</td>" for i, c in enumerate(r)) + "</tr>" for r in rows)
            out.append(f"<table>{h}{b}</table>")
            table.clear()

    for line in text.splitlines():
        if line.startswith("|"):
            if bullets:
                flush()
            table.append(line)
            continue
        if table:
            flush()
        if line.startswith("#"):
            flush()
            level = min(len(line) - len(line.lstrip("#")) + 1, 4)
            out.append(f"<h{level}>{esc(line.lstrip('#').strip())}</h{level}>")
        elif line.startswith("- "):
            bullets.append(line[2:])
        elif line.strip():
            flush()
            out.append(f"<p>{esc(line)}</p>")
        else:
            flush()
    flush()
    return "\n".join(out)
