#!/usr/bin/python3
"""How well can GNSS velocity and position tell the heading before the GNSS loss? (docs/navigation.md,
"In-flight fine alignment".)

  tools/report/heading_bound.py --run RUN_DIR [--batch LABEL=DIR ...] [--heading-sigma-deg 5] [--tilt-sigma-deg 1.5]
                                [--no-gyro-noise] [--png FILE]

From the true trajectory of one run (RUN_DIR/run.h5, truth at the recorder's rate) it runs the covariance of a linear
Kalman filter on the horizontal INS error model

  d(dp_NE)/dt = dv_NE
  d(dv_N)/dt  =  psi f_E - theta_E f_D + (R_h(yaw) E_xy)_N + w_v
  d(dv_E)/dt  = -psi f_N + theta_N f_D + (R_h(yaw) E_xy)_E + w_v
  d(theta_N, theta_E, psi)/dt = w_g,   d(E_xy)/dt = w_b

  d(theta_N, theta_E, psi)/dt = -R_h(yaw) E_gyr + w_g,   d(E_xy)/dt = w_b,   d(E_gyr)/dt = w_u

with f_NED the true specific force (from the true ground velocity), fed by the GNSS fixes of the sensor model (position
white sigma, velocity white sigma, one per fix period) until the GNSS loss, and by the magnetometer as a compass at
every truth sample: psi_mag = psi + c0 + c1 cos(yaw) + c2 sin(yaw) + noise, where c0 (the NED-fixed field error B_dev,
which cannot be told from the heading) starts at the truth-free start's heading sigma and c1, c2 (hard iron and bias
offset, body-fixed) at their sensor sigma over the horizontal field. Its heading sigma is what an ideal filter with
these sensors could know. It is favourable to the filter in what it leaves out (scale errors, the ionospheric walk,
the vertical channel, the magnetometer's soft iron), so the true limit is above it. With --batch, the heading error
|psi_hat - psi| at the GNSS loss of each run of the batches (run.h5 error/yaw_rad) is printed beside it (median, rms,
90th percentile; runs whose mean attitude error is above 20 deg left out as diverged). With --png: the sigma against
time with the GNSS loss marked. The whole run, tilt and heading, after the loss too: attitude_bound.py, which imports
this module's input and batch helpers (they raise InputError; each tool prints it as its own one line).
Debian's python3-h5py, -numpy, -yaml, -matplotlib.
"""
import argparse
import math
import os
import sys

import h5py
import numpy as np
import yaml

DEG = 180.0 / math.pi
G = 9.80665


class InputError(Exception):
    """Bad input (a missing or malformed file or folder, a bad option): the tools print it as one line and exit."""


def fail(msg):
    sys.exit(f"heading_bound: {msg}")


def load_yaml(path, what):
    if not os.path.isfile(path):
        raise InputError(f"'{path}' not found ({what})")
    try:
        with open(path) as fh:
            return yaml.safe_load(fh)
    except yaml.YAMLError as e:
        raise InputError(f"'{path}' is not valid YAML ({what}): {str(e).splitlines()[0]}") from None


def sensor_figures(config_dir, grades=None):
    """GNSS, accelerometer, gyroscope and magnetometer figures from config/sensors (SI); GRADES maps a group
    (gnss, accelerometers, gyroscopes, magnetometers) to its grade, baseline where not given."""
    grades = grades or {}

    def grade(group, what):
        name = grades.get(group, "baseline")
        return load_yaml(os.path.join(config_dir, f"sensors/{group}/{name}.yaml"), f"{what} grade '{name}'")

    gnss = grade("gnss", "GNSS")
    acc = grade("accelerometers", "accelerometer")
    gyr = grade("gyroscopes", "gyroscope")
    mag = grade("magnetometers", "magnetometer")
    field = load_yaml(os.path.join(config_dir, "earth/magnetic_wisconsin.yaml"), "magnetic model")
    b_h = math.hypot(*field["b_n_lat_min_lon_min_nT"][:2])
    return {
        "pos_m": float(gnss["horizontal_noise_m"]), "vel_mps": float(gnss["velocity_noise_m_s"]), "fix_s": float(gnss["fix_period_s"]),
        "acc_white": float(acc["system_noise_m_s1p5"]), "acc_walk": float(acc["bias_drift_m_s2p5"]),
        "acc_offset": float(acc["bias_offset_m_s2"]), "gyr_white": float(gyr["system_noise_deg_s0p5"]) / DEG,
        "gyr_walk": float(gyr["bias_drift_deg_s1p5"]) / DEG, "gyr_offset": float(gyr["bias_offset_deg_s"]) / DEG,
        "mag_white_rad": float(mag["system_noise_nT_s0p5"]) / b_h,
        "mag_body_rad": math.hypot(float(mag["hard_iron_nT"]), float(mag["bias_offset_nT"])) / b_h,
    }


def truth_of(run_dir):
    path = os.path.join(run_dir, "run.h5")
    if not os.path.isfile(path):
        raise InputError(f"'{path}' not found (--run takes a run folder of gdnav run or montecarlo)")
    with h5py.File(path, "r") as f:
        tr = f["truth"][...]
    meta = load_yaml(os.path.join(run_dir, "metrics.yaml"), "the run's metrics")
    return tr, float(meta["t_gnss_s"])


def heading_sigma(tr, t_gnss_s, s, heading0_rad, tilt0_rad, gyro_noise):
    """Heading sigma [rad] of the ideal filter at each truth sample up to the GNSS loss; times [s]."""
    t = tr["t_s"]
    vn, ve, vd = tr["vn_mps"], tr["ve_mps"], tr["vd_mps"]
    f_n, f_e = np.gradient(vn, t), np.gradient(ve, t)
    f_d = np.gradient(vd, t) - G
    yaw = tr["yaw_rad"]
    n = 15  # dpN dpE dvN dvE thN thE psi Ex Ey Egx Egy Egz c0 c1 c2
    p = np.diag([10.0 ** 2] * 2 + [0.5 ** 2] * 2 + [tilt0_rad ** 2] * 2 + [(6.0 * heading0_rad) ** 2]
                + [s["acc_offset"] ** 2] * 2 + [s["gyr_offset"] ** 2] * 3 + [heading0_rad ** 2]
                + [s["mag_body_rad"] ** 2] * 2)
    h = np.zeros((4, n))
    h[0, 0] = h[1, 1] = h[2, 2] = h[3, 3] = 1.0
    r = np.diag([s["pos_m"] ** 2] * 2 + [s["vel_mps"] ** 2] * 2)
    next_fix = t[0] + s["fix_s"]
    times, sig = [], []
    for k in range(0, len(t)):
        if t[k] > t_gnss_s + 1e-9:
            break
        c, sn = math.cos(yaw[k]), math.sin(yaw[k])
        if k > 0:
            dt = t[k] - t[k - 1]
            a = np.zeros((n, n))
            a[0, 2] = a[1, 3] = 1.0
            a[2, 6], a[2, 5] = f_e[k - 1], -f_d[k - 1]
            a[3, 6], a[3, 4] = -f_n[k - 1], f_d[k - 1]
            a[2, 7], a[2, 8], a[3, 7], a[3, 8] = c, -sn, sn, c
            a[4, 9], a[4, 10], a[5, 9], a[5, 10], a[6, 11] = -c, sn, -sn, -c, -1.0
            phi = np.eye(n) + a * dt + 0.5 * (a @ a) * dt * dt
            q = np.zeros(n)
            q[2] = q[3] = s["acc_white"] ** 2 * dt
            if gyro_noise:
                q[4] = q[5] = q[6] = s["gyr_white"] ** 2 * dt
            q[7] = q[8] = s["acc_walk"] ** 2 * dt
            q[9] = q[10] = q[11] = s["gyr_walk"] ** 2 * dt
            p = phi @ p @ phi.T + np.diag(q)
        # The compass: one heading per truth sample, its white noise averaged over the sample interval.
        hm = np.zeros(n)
        hm[6], hm[12], hm[13], hm[14] = 1.0, 1.0, c, sn
        pm = p @ hm
        p = p - np.outer(pm, pm) / (hm @ pm + s["mag_white_rad"] ** 2 / (t[1] - t[0]))
        if k > 0 and t[k] >= next_fix - 1e-9:
            next_fix += s["fix_s"]
            k_gain = p @ h.T @ np.linalg.inv(h @ p @ h.T + r)
            p = (np.eye(n) - k_gain @ h) @ p
        p = 0.5 * (p + p.T)
        times.append(t[k])
        sig.append(math.sqrt(p[6, 6]))
    return np.array(times), np.array(sig)


def complete_runs(batch):
    """(run folder, its metrics) of each run of a montecarlo batch folder with run.h5 and a complete metrics.yaml,
    in run order."""
    root = os.path.join(batch, "runs")
    if not os.path.isdir(root):
        raise InputError(f"'{batch}' has no runs/ folder (not a gdnav montecarlo batch)")
    out = []
    for name in sorted(os.listdir(root)):
        run = os.path.join(root, name)
        mfile, hfile = os.path.join(run, "metrics.yaml"), os.path.join(run, "run.h5")
        if not (os.path.isfile(mfile) and os.path.isfile(hfile)):
            continue
        m = load_yaml(mfile, "metrics")
        if isinstance(m, dict) and m.get("complete") is True:
            out.append((run, m))
    return out


def diverged(m, diverged_deg=20.0):
    """A run whose mean attitude error is above DIVERGED_DEG: the filter lost the attitude."""
    return m["signals"]["rot_rad"]["mean"] * DEG > diverged_deg


def heading_error_at_loss_deg(run, m):
    """|psi_hat - psi| [deg] at the run.h5 row nearest the GNSS loss."""
    with h5py.File(os.path.join(run, "run.h5"), "r") as f:
        e = f["error"][...]
    i = int(np.argmin(np.abs(e["t_s"] - float(m["t_gnss_s"]))))
    return abs(e["yaw_rad"][i]) * DEG


def heading_errors_at_loss(batch, diverged_deg=20.0):
    out = [heading_error_at_loss_deg(run, m) for run, m in complete_runs(batch) if not diverged(m, diverged_deg)]
    if not out:
        raise InputError(f"'{batch}' has no complete, non-diverged run with run.h5")
    return np.array(out)


def main():
    try:
        run_main()
    except InputError as e:
        fail(str(e))


def run_main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("--run", required=True, help="run folder whose true trajectory is used")
    ap.add_argument("--batch", action="append", default=[], help="LABEL=DIR: heading errors at the loss")
    ap.add_argument("--heading-sigma-deg", type=float, default=5.0)
    ap.add_argument("--tilt-sigma-deg", type=float, default=1.5)
    ap.add_argument("--no-gyro-noise", action="store_true", help="angles without the gyro white noise")
    ap.add_argument("--config-dir", default=os.path.join(os.path.dirname(__file__), "../../config"))
    ap.add_argument("--png")
    a = ap.parse_args()
    for name, v in (("--heading-sigma-deg", a.heading_sigma_deg), ("--tilt-sigma-deg", a.tilt_sigma_deg)):
        if not (0.0 < v <= 90.0):
            fail(f"{name} must be in (0, 90] deg, got {v}")
    batches = []
    for b in a.batch:
        if "=" not in b:
            fail(f"--batch takes LABEL=DIR, got '{b}'")
        label, d = b.split("=", 1)
        batches.append((label, d))
    s = sensor_figures(a.config_dir)
    tr, t_gnss = truth_of(a.run)
    times, sig = heading_sigma(tr, t_gnss, s, a.heading_sigma_deg / DEG, a.tilt_sigma_deg / DEG, not a.no_gyro_noise)
    print(f"ideal heading sigma at the GNSS loss (t = {t_gnss:g} s), from a start at {a.heading_sigma_deg:g} deg / "
          f"tilt {a.tilt_sigma_deg:g} deg, gyro white noise {'off' if a.no_gyro_noise else 'on'}: "
          f"{sig[-1] * DEG:.3f} deg (lowest on the way {sig.min() * DEG:.3f} deg at t = {times[np.argmin(sig)]:.0f} s)")
    print("| batch | runs (not diverged) | |heading error| at the loss: median | rms | 90th percentile |")
    print("|---|--:|--:|--:|--:|")
    for label, d in batches:
        e = heading_errors_at_loss(d)
        print(f"| {label} | {len(e)} | {np.median(e):.3f}° | {math.sqrt(np.mean(e ** 2)):.3f}° | "
              f"{np.percentile(e, 90):.3f}° |")
    if a.png:
        import matplotlib
        matplotlib.use("Agg")
        import matplotlib.pyplot as plt
        fig, ax = plt.subplots(figsize=(8, 4.5))
        ax.semilogy(times, sig * DEG, label="ideal filter heading σ (GNSS position + velocity)")
        # Batches side by side (a few seconds apart) so that equal values stay visible.
        for i, (label, d) in enumerate(batches):
            e = heading_errors_at_loss(d)
            ax.plot([t_gnss + 4.0 * (i - (len(batches) - 1) / 2.0)], [math.sqrt(np.mean(e ** 2))], "osD^v"[i % 5],
                    label=f"{label}: rms |heading error| at the loss")
        ax.axvline(t_gnss, color="k", lw=0.8, ls="--")
        ax.set_xlabel("t [s] (GNSS lost at the dashed line)")
        ax.set_ylabel("heading [deg]")
        ax.set_title("What GNSS can tell of the heading before the loss")
        ax.grid(True, which="both", alpha=0.3)
        ax.legend(fontsize=8)
        fig.tight_layout()
        fig.savefig(a.png, dpi=110)
        print(f"figure: {a.png}")


if __name__ == "__main__":
    main()
