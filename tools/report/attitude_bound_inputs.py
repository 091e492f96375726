"""The inputs of attitude_bound.py: one run folder (run.h5 /truth and /error, metrics.yaml, run.yaml) and the config,
turned into the sensor figures of the run and per-row arrays of its truth.

Figures: the run's sensor grades (run.yaml sensors_* grade keys, else config/sensors/suite.yaml) in config/sensors
(noise densities, bias walks and offsets, the magnetometer's scale and cross-coupling, GNSS and air-data sigmas);
suite.yaml (sample period, the drift band N, the alignment's errors, the mounting estimate error); the tuning file
(the truth-free start's sigmas, the field model's error budget); the start mode (run.yaml nav_att.init_mode, else the
tuning file's); the model field (config/earth, bilinear at the true position).
Numbers not in config, derived:
  * Bias drifts: the walk (sigma_u per sqrt(s)) is reflected at +-N sigma_u sqrt(dt_s) (N = bias_drift_band, dt_s the
    sensor period; docs/sensors.md), so after about N^2 dt_s it is spread evenly over the band. The model is a
    Gauss-Markov process with the band's variance (N sigma_u sqrt(dt_s))^2/3 and the walk's increment sigma_u^2 dt,
    i.e. the time constant 2 N^2 dt_s / 3 (67 s for N = 100).
  * Turbulence: the truth's wind columns hold the wind ramp only, so the turbulence is v - C v_air - w_ramp of the
    truth, per NED axis. Its sigma per axis and one time constant (the mean over the axes of the integral time scale
    of its autocorrelation, up to its first zero) are the run's own: the model has the truth's low-frequency
    spectrum, which decides how well a slope (a tilt) is told from the wind.
  * The wind's constant part walks while the true wind ramps (the truth's rows where it changes) with the density
    (ramp change)^2 / (ramp duration) per axis: as far as the ramp goes. None in scenario #2 (no ramp).
"""
import math
import os

import h5py
import numpy as np

import heading_bound as hb
from heading_bound import DEG, G, InputError

ROW_S = 0.1  # the truth rows are thinned to about this step: the recorder's default rate


def dcm_body_to_ned(yaw, pitch, bank):
    """C_bn of ZYX Euler angles, (K,) each -> (K, 3, 3)."""
    cy, sy, cp, sp, cb, sb = np.cos(yaw), np.sin(yaw), np.cos(pitch), np.sin(pitch), np.cos(bank), np.sin(bank)
    c = np.empty(yaw.shape + (3, 3))
    c[:, 0, 0], c[:, 0, 1], c[:, 0, 2] = cp * cy, sb * sp * cy - cb * sy, cb * sp * cy + sb * sy
    c[:, 1, 0], c[:, 1, 1], c[:, 1, 2] = cp * sy, sb * sp * sy + cb * cy, cb * sp * sy - sb * cy
    c[:, 2, 0], c[:, 2, 1], c[:, 2, 2] = -sp, sb * cp, cb * cp
    return c


def get_path(doc, *keys):
    for k in keys:
        if not isinstance(doc, dict) or k not in doc:
            return None
        doc = doc[k]
    return doc


def run_inputs(run_dir, config_dir):
    """Everything a bound needs from one run folder (run.h5, metrics.yaml, run.yaml) and the config."""
    if not os.path.isdir(run_dir):
        raise InputError(f"'{run_dir}' is not a folder (--run takes a run folder of gdnav run or montecarlo)")
    path = os.path.join(run_dir, "run.h5")
    if not os.path.isfile(path):
        raise InputError(f"'{path}' not found (--run takes a run folder of gdnav run or montecarlo)")
    try:
        with h5py.File(path, "r") as f:
            if "truth" not in f:
                raise InputError(f"'{path}' has no /truth table (not a nav_recorder file)")
            tr = f["truth"][...]
            err = f["error"][...] if "error" in f else None
    except OSError as e:
        raise InputError(f"'{path}' cannot be read as HDF5 ({e})") from None
    need = ("t_s", "lat_rad", "lon_rad", "vn_mps", "ve_mps", "vd_mps", "yaw_rad", "pitch_rad", "bank_rad", "tas_mps",
            "aoa_rad", "aos_rad", "wind_n_mps", "wind_e_mps", "wind_d_mps")
    missing = [c for c in need if tr.dtype.names is None or c not in tr.dtype.names]
    if missing:
        raise InputError(f"'{path}' /truth lacks the columns {', '.join(missing)}")
    if len(tr) < 3:
        raise InputError(f"'{path}' has {len(tr)} truth rows: too short for a bound")
    if not all(np.all(np.isfinite(tr[c])) for c in need):
        raise InputError(f"'{path}' has no reference trajectory (NaN truth; a replay without one?)")
    m = hb.load_yaml(os.path.join(run_dir, "metrics.yaml"), "the run's metrics")
    cfg = hb.load_yaml(os.path.join(run_dir, "run.yaml"), "the run's resolved configuration")
    if not isinstance(m, dict) or not isinstance(cfg, dict):
        raise InputError(f"'{run_dir}': metrics.yaml or run.yaml is not a mapping")
    try:
        t_gnss, t_end = float(m["t_gnss_s"]), float(m["t_end_s"])
    except (KeyError, TypeError, ValueError):
        raise InputError(f"'{run_dir}/metrics.yaml' lacks t_gnss_s or t_end_s (an incomplete run?)") from None
    comps = cfg.get("components") or {}
    t_start = float(get_path(comps, "nav_recorder", "metrics_start_s") or 0.0)
    if not (tr["t_s"][0] <= t_gnss <= tr["t_s"][-1]) or not (t_start < t_end):
        raise InputError(f"'{run_dir}': GNSS loss at {t_gnss:g} s or window [{t_start:g}, {t_end:g}] s outside the "
                         f"truth's [{tr['t_s'][0]:g}, {tr['t_s'][-1]:g}] s")
    return {"dir": run_dir, "truth": tr, "error": err, "metrics": m, "t_gnss_s": t_gnss, "t_end_s": t_end,
            "t_start_s": t_start, "figures": figures(config_dir, comps)}


def figures(config_dir, comps):
    """Sensor, alignment and start figures of a run (SI) from config/, with the run's own grades and band."""
    suite_rel = get_path(comps, "sensors_inertial", "suite") or "sensors/suite.yaml"
    suite = hb.load_yaml(os.path.join(config_dir, suite_rel), "sensor suite")
    grades = {g: get_path(suite, g, "grade") or "baseline"
              for g in ("gyroscopes", "accelerometers", "magnetometers", "air_data", "gnss")}
    for group, comp, key in (("gyroscopes", "sensors_inertial", "gyr_grade"),
                             ("accelerometers", "sensors_inertial", "acc_grade"),
                             ("magnetometers", "sensors_magnetic", "grade"), ("air_data", "sensors_air", "grade"),
                             ("gnss", "sensors_gnss", "grade")):
        if get_path(comps, comp, key):
            grades[group] = get_path(comps, comp, key)
    s = hb.sensor_figures(config_dir, grades)
    gnss = hb.load_yaml(os.path.join(config_dir, f"sensors/gnss/{grades['gnss']}.yaml"), "GNSS grade")
    air = hb.load_yaml(os.path.join(config_dir, f"sensors/air_data/{grades['air_data']}.yaml"), "air data grade")
    mag = hb.load_yaml(os.path.join(config_dir, f"sensors/magnetometers/{grades['magnetometers']}.yaml"),
                       "magnetometer grade")
    field = hb.load_yaml(os.path.join(config_dir, get_path(comps, "flight_physics", "magnetic_model")
                                      or "earth/magnetic_wisconsin.yaml"), "magnetic model")
    tuning = hb.load_yaml(os.path.join(config_dir, get_path(comps, "nav_att", "tuning") or "nav/tuning.yaml"),
                          "navigation tuning")
    init_m = get_path(tuning, "attitude", "init", "measurements") or {}
    band = get_path(comps, "sensors_inertial", "bias_drift_band")
    band = suite["bias_drift_band"] if band is None else band
    align = suite.get("alignment") or {}
    platform = suite.get("platform") or {}
    try:
        s.update({
            "pos_v_m": float(gnss["vertical_noise_m"]), "mag_white_nT": float(mag["system_noise_nT_s0p5"]),
            "mag_body_nT": math.hypot(float(mag["hard_iron_nT"]), float(mag["bias_offset_nT"])),
            "mag_scale": float(mag["scale_factor"]), "mag_cross": float(mag["cross_coupling"]),
            "tas_white_mps": float(air["tas_noise_m_s"]), "aoa_white_rad": float(air["aoa_noise_deg"]) / DEG,
            "aos_white_rad": float(air["aos_noise_deg"]) / DEG, "tas_offset_mps": float(air["tas_bias_offset_m_s"]),
            "aoa_offset_rad": float(air["aoa_bias_offset_deg"]) / DEG,
            "aos_offset_rad": float(air["aos_bias_offset_deg"]) / DEG,
            "sample_s": float(suite["sample_period_s"]), "band": float(band),
            "mount_rad": float(platform["mounting_estimate_error_deg"]) / DEG,
            "align_att_rad": float(align["att_error_sigma_deg"]) / DEG,
            "align_gyr_rel": float(align["gyr_rel_error"]), "align_acc_rel": float(align["acc_rel_error"]),
            "align_mag_rel": float(align["mag_rel_error"]), "align_bdev_rel": float(align["b_dev_rel_error"]),
            "tf_tilt_rad": float(init_m["tilt_sigma_deg"]) / DEG,
            "tf_heading_rad": float(init_m["heading_sigma_deg"]) / DEG,
            "bdev_budget_nT": np.array(init_m["b_dev_sigma_nT"], dtype=float),
            "field": {k: np.array(field[k], dtype=float) if isinstance(field[k], list) else float(field[k])
                      for k in ("lat_min_deg", "lat_max_deg", "lon_min_deg", "lon_max_deg", "b_n_lat_min_lon_min_nT",
                                "b_n_lat_min_lon_max_nT", "b_n_lat_max_lon_min_nT", "b_n_lat_max_lon_max_nT")},
        })
    except (KeyError, TypeError, ValueError) as e:
        raise InputError(f"a figure of the sensor suite, grades or tuning file is missing or not a number "
                         f"({e})") from None
    mode = get_path(comps, "nav_att", "init_mode") or get_path(tuning, "attitude", "init", "mode") or "alignment"
    if mode not in ("alignment", "measurements"):
        raise InputError(f"unknown init_mode '{mode}' (alignment or measurements)")
    s["init_mode"] = mode
    # Bias drifts: the reflected walk as a Gauss-Markov process of the band's variance and the walk's increments.
    s["drift_tau_s"] = 2.0 * s["band"] ** 2 * s["sample_s"] / 3.0 if s["band"] > 0 else math.inf
    bdev = get_path(comps, "flight_physics", "earth_truth", "mag_dev_n_nT")
    s["bdev_true_nT"] = np.array(bdev, dtype=float) if bdev is not None else None
    return s


def field_ned_nT(fd, lat_rad, lon_rad):
    """The model field at each position: bilinear between the file's four corners, linear outside (config/earth)."""
    x = (lat_rad * DEG - fd["lat_min_deg"]) / (fd["lat_max_deg"] - fd["lat_min_deg"])
    y = (lon_rad * DEG - fd["lon_min_deg"]) / (fd["lon_max_deg"] - fd["lon_min_deg"])
    x, y = x[:, None], y[:, None]
    return ((1 - x) * (1 - y) * fd["b_n_lat_min_lon_min_nT"] + x * (1 - y) * fd["b_n_lat_max_lon_min_nT"]
            + (1 - x) * y * fd["b_n_lat_min_lon_max_nT"] + x * y * fd["b_n_lat_max_lon_max_nT"])


def integral_time_scale_s(x, dt):
    """Integral of the autocorrelation of X (mean removed) up to its first zero, times DT."""
    x = x - x.mean()
    n = len(x)
    spec = np.fft.rfft(x, 2 * n)
    ac = np.fft.irfft(spec * np.conj(spec))[:n]
    if ac[0] <= 0.0:
        return 0.0
    ac = ac / ac[0]
    stop = np.argmax(ac <= 0.0) if np.any(ac <= 0.0) else n
    return float(ac[:stop].sum() * dt)


def trajectory(tr, s):
    """Per-row arrays of the truth (thinned to about ROW_S): times, steps, C_bn, f_n, v_air_n, J, B_n, wind ramp."""
    t_all = tr["t_s"]
    stride = max(1, int(round(ROW_S / float(np.median(np.diff(t_all))))))
    tr = tr[::stride]
    t = tr["t_s"]
    dt = np.diff(t)
    if np.any(dt <= 0.0):
        raise InputError("the truth's times do not increase")
    c = dcm_body_to_ned(tr["yaw_rad"], tr["pitch_rad"], tr["bank_rad"])
    v = np.stack([tr["vn_mps"], tr["ve_mps"], tr["vd_mps"]], 1)
    f_n = np.stack([np.gradient(v[:, i], t) for i in range(3)], 1)
    f_n[:, 2] -= G
    vt, al, be = tr["tas_mps"], tr["aoa_rad"], tr["aos_rad"]
    ca, sa, cb, sb = np.cos(al), np.sin(al), np.cos(be), np.sin(be)
    v_air_b = np.stack([vt * ca * cb, vt * sb, vt * sa * cb], 1)
    jac = np.empty((len(t), 3, 3))  # columns: d v_air_b / d(TAS, AOA, AOS)
    jac[:, :, 0] = np.stack([ca * cb, sb, sa * cb], 1)
    jac[:, :, 1] = (vt[:, None] * np.stack([-sa * cb, np.zeros_like(vt), ca * cb], 1))
    jac[:, :, 2] = (vt[:, None] * np.stack([-ca * sb, cb, -sa * sb], 1))
    v_air_n = np.einsum("kij,kj->ki", c, v_air_b)
    wind = np.stack([tr["wind_n_mps"], tr["wind_e_mps"], tr["wind_d_mps"]], 1)
    return {"t_s": t, "dt_s": dt, "c": c, "f_n_mps2": f_n, "v_air_n_mps": v_air_n, "jac": jac, "wind_n_mps": wind,
            "v_n_mps": v, "b_n_nT": field_ned_nT(s["field"], tr["lat_rad"], tr["lon_rad"])}


def wind_models(traj):
    """Turbulence sigma per axis and time constant, and the ramp's random-walk density per row (N, E), from the
    truth."""
    dt = float(np.median(traj["dt_s"]))
    turb = traj["v_n_mps"] - traj["v_air_n_mps"] - traj["wind_n_mps"]
    sig = turb.std(axis=0)
    scales = [integral_time_scale_s(turb[:, i], dt) for i in range(3) if sig[i] > 1e-9]
    # Without turbulence its time constant is never used; with it, at least two rows keep the discrete
    # transition I + A dt + (A dt)^2 / 2 of the Gauss-Markov state stable.
    tau = max(float(np.mean(scales)) if scales else 1.0, 2.0 * dt)
    dw = np.diff(traj["wind_n_mps"][:, :2], axis=0)
    moving = np.any(np.abs(dw) > 1e-9, axis=1)
    q = np.zeros((len(traj["dt_s"]), 2))
    if np.any(moving):
        span = float(traj["dt_s"][moving].sum())
        q[moving] = dw[moving].sum(axis=0) ** 2 / span
    return sig, tau, q


def filter_figures(inp):
    """The run's own filter: mean ||dr_hat|| over the metric's window (metrics.yaml) and |heading error| at the loss."""
    try:
        rot = float(inp["metrics"]["signals"]["rot_rad"]["mean"])
    except (KeyError, TypeError, ValueError):
        rot = math.nan
    try:
        head = hb.heading_error_at_loss_deg(inp["dir"], inp["metrics"]) / DEG
    except (KeyError, ValueError):
        head = math.nan
    return rot, head
