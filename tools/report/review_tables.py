"""The tables of review.py's run pages: the run's metrics (metrics.yaml) as rows of text, and the number format
shared by the run and batch pages."""
import math

from batch_runs import DEG, final_distance, signal, stopped_note


def fmt(v, digits=2, signed=False):
    if v is None or not math.isfinite(v):
        return "n/a"
    return f"{v:+.{digits}f}" if signed else f"{v:.{digits}f}"


def run_summary_rows(m):
    if m.get("reference") == "none":
        return [("complete", str(m.get("complete"))),
                ("reference", "none: no reference trajectory, so no error metrics (docs/replay.md)")]
    note = stopped_note(m)
    t_end = float(m.get("t_end_s", float("nan")))
    final = f"final at t = {t_end:.2f} s" if note else "final"
    rows = [("complete", str(m.get("complete")))]
    if note:
        rows.append(("estimates", "INCOMPLETE: " + note))
    rows += [("t_end [s]", fmt(t_end, 1))]
    if note:
        rows += [("distance since t_GNSS up to t_end [m]", fmt(final_distance(m), 0)),
                 ("distance since t_GNSS to the end of the flight [m]",
                  fmt(float(m.get("distance_since_gnss_m") or float("nan")), 0))]
    else:
        rows.append(("distance since t_GNSS [m]", fmt(float(m.get("distance_since_gnss_m") or float("nan")), 0)))
    pct = m.get("final_percent") or {}
    for key, lab in (("hor_m", "Δx_hor"), ("cross_m", "Δx_cross"), ("along_m", "Δx_along")):
        p = pct.get(key.split("_")[0])
        rows.append((f"{final} {lab} [m]", fmt(signal(m, key, "final"), 1, key != "hor_m") +
                     (f" ({fmt(float(p), 2, key != 'hor_m')} %)" if p is not None else "")))
    rows += [(f"{final} ĥ−h [m]", fmt(signal(m, "h_m", "final"), 2, True)),
             (f"{final} v̂_N−v_N, v̂_E−v_E [m/s]",
              fmt(signal(m, "vn_mps", "final"), 2, True) + ", " + fmt(signal(m, "ve_mps", "final"), 2, True)),
             ("‖Δr̂‖ mean, max [deg]",
              fmt(signal(m, "rot_rad", "mean") * DEG, 3) + ", " + fmt(abs(signal(m, "rot_rad", "max")) * DEG, 3))]
    return rows
