"""tools/report/attitude_bound.py (the whole-run attitude bound; its model and inputs modules) on a synthetic run
folder it writes itself: a straight level leg, a 360-degree turn each way, a straight leg to the GNSS loss and on to
the end. Run by CTest (Tools.AttitudeBound) with PYTHONPATH=tools/report."""
import contextlib
import io
import math
import os
import tempfile
import unittest

import h5py
import numpy as np
import yaml

import attitude_bound as ab
import attitude_bound_inputs as ai
import attitude_bound_model as am

G = 9.80665
DEG = 180.0 / math.pi
V_MPS = 30.0
BANK_RAD = 20.0 / DEG
RATE_RPS = G * math.tan(BANK_RAD) / V_MPS   # coordinated turn at 20 deg of bank
TURN_S = 2.0 * math.pi / RATE_RPS            # 52.8 s per full turn
T0_S, STRAIGHT_S, T_GNSS_S, T_END_S = -100.0, 60.0, 100.0, 250.0
T_TURNS_END_S = T0_S + STRAIGHT_S + 2.0 * TURN_S
TRUTH_COLS = ("t_s lat_rad lon_rad h_m vn_mps ve_mps vd_mps yaw_rad pitch_rad bank_rad tas_mps aoa_rad aos_rad "
              "wind_n_mps wind_e_mps wind_d_mps").split()
ERROR_COLS = ("t_s", "yaw_rad", "rot_rad")


def truth_rows(dt_s=0.1):
    """Level flight at V_MPS, no wind: north, a right turn, a left turn (back north), then north to the end."""
    t = T0_S + dt_s * np.arange(int(round((T_END_S - T0_S) / dt_s)) + 1)
    t1, t2 = T0_S + STRAIGHT_S, T0_S + STRAIGHT_S + TURN_S
    rate = np.where((t >= t1) & (t < t2), RATE_RPS, np.where((t >= t2) & (t < T_TURNS_END_S), -RATE_RPS, 0.0))
    yaw = RATE_RPS * (np.clip(t, t1, t2) - t1) - RATE_RPS * (np.clip(t, t2, T_TURNS_END_S) - t2)
    yaw = np.angle(np.exp(1j * yaw))
    vn, ve = V_MPS * np.cos(yaw), V_MPS * np.sin(yaw)
    north = np.concatenate([[0.0], np.cumsum(0.5 * (vn[1:] + vn[:-1]) * dt_s)])
    east = np.concatenate([[0.0], np.cumsum(0.5 * (ve[1:] + ve[:-1]) * dt_s)])
    tr = np.zeros(len(t), dtype=[(c, "f8") for c in TRUTH_COLS])
    tr["t_s"], tr["yaw_rad"], tr["vn_mps"], tr["ve_mps"] = t, yaw, vn, ve
    tr["lat_rad"] = 45.0 / DEG + north / 6.371e6
    tr["lon_rad"] = -90.0 / DEG + east / (6.371e6 * math.cos(45.0 / DEG))
    tr["h_m"] = 2500.0
    tr["bank_rad"] = np.arctan(V_MPS * rate / G)
    tr["tas_mps"] = V_MPS  # no wind, pitch and AOA 0: the air velocity is the ground velocity
    return tr


def write_run(folder, init_mode="measurements", rot_mean_rad=0.002, band=None, nan_truth=False):
    os.makedirs(folder, exist_ok=True)
    tr = truth_rows()
    if nan_truth:
        tr["lat_rad"] = np.nan
    err = np.zeros(len(tr), dtype=[(c, "f8") for c in ERROR_COLS])
    err["t_s"], err["yaw_rad"], err["rot_rad"] = tr["t_s"], 0.5 * rot_mean_rad, rot_mean_rad
    with h5py.File(os.path.join(folder, "run.h5"), "w") as f:
        f.attrs["complete"] = 1
        f.create_dataset("truth", data=tr)
        f.create_dataset("error", data=err)
    with open(os.path.join(folder, "metrics.yaml"), "w") as fh:
        yaml.safe_dump({"complete": True, "t_gnss_s": T_GNSS_S, "t_end_s": T_END_S,
                        "signals": {"rot_rad": {"mean": rot_mean_rad, "std": 0.0, "max": rot_mean_rad,
                                                "final": rot_mean_rad}}}, fh)
    inertial = {"type": "sensors_inertial", "suite": "sensors/suite.yaml"}
    if band is not None:
        inertial["bias_drift_band"] = band
    with open(os.path.join(folder, "run.yaml"), "w") as fh:
        yaml.safe_dump({"run": {"t0_s": T0_S}, "components": {
            "flight_physics": {"magnetic_model": "earth/magnetic_wisconsin.yaml"}, "sensors_inertial": inertial,
            "nav_att": {"type": "nav_att", "tuning": "nav/tuning.yaml", "init_mode": init_mode},
            "nav_recorder": {"type": "nav_recorder", "t_gnss_s": T_GNSS_S}}}, fh)
    return folder


CONFIG = os.path.join(os.path.dirname(os.path.abspath(ab.__file__)), "../../config")


def bound(folder, **kw):
    return am.run_bound(ai.run_inputs(folder, CONFIG), **kw)


def at(b, t_s):
    return int(np.argmin(np.abs(b["t_s"] - t_s)))


def main_cli(*args):
    out, err = io.StringIO(), io.StringIO()
    with contextlib.redirect_stdout(out), contextlib.redirect_stderr(err):
        code = ab.main(list(args))
    return code, out.getvalue(), err.getvalue()


class ExpectedNorm(unittest.TestCase):
    def test_closed_forms(self):
        # E||x||: isotropic sigma^2 I -> sigma E[chi_3] = 2 sigma sqrt(2/pi); rank one -> sigma sqrt(2/pi) (E|z|);
        # rank two, isotropic in a plane -> sigma sqrt(pi/2) (Rayleigh).
        cov = np.array([4.0 * np.eye(3), np.diag([9.0, 0.0, 0.0]), np.diag([0.0, 1.0, 1.0])])
        en = am.expected_norm(cov)
        self.assertAlmostEqual(en[0], 2.0 * 2.0 * math.sqrt(2.0 / math.pi), delta=1e-9)
        self.assertAlmostEqual(en[1] / (3.0 * math.sqrt(2.0 / math.pi)), 1.0, delta=1e-4)
        self.assertAlmostEqual(en[2] / math.sqrt(math.pi / 2.0), 1.0, delta=1e-4)
        # Not sqrt(trace): for sigma^2 I, sqrt(trace) = sigma sqrt(3) = 1.73 sigma against 1.60 sigma.
        self.assertLess(en[0], math.sqrt(12.0) * 0.95)

    def test_rotation_invariant(self):
        rng = np.random.default_rng(1)
        q, _ = np.linalg.qr(rng.normal(size=(3, 3)))
        d = np.diag([1.0, 0.25, 0.01])
        en = am.expected_norm(np.array([d, q @ d @ q.T]))
        self.assertAlmostEqual(en[0] / en[1], 1.0, delta=2e-4)


class SyntheticRun(unittest.TestCase):
    @classmethod
    def setUpClass(cls):
        cls.tmp = tempfile.TemporaryDirectory()
        # A drift band so wide that the bias drift is the plain random walk over these few minutes.
        cls.run_dir = write_run(os.path.join(cls.tmp.name, "run"), band=1e6)
        cls.gnss_only = bound(cls.run_dir, magnetometer="none", air_data=False)
        cls.full = bound(cls.run_dir)
        cls.air_no_mag = bound(cls.run_dir, magnetometer="none")

    @classmethod
    def tearDownClass(cls):
        cls.tmp.cleanup()

    def test_straight_leg_tells_nothing_of_the_heading_a_turn_does(self):
        b, s = self.gnss_only, self.gnss_only["figures"]
        start, end_straight = b["heading_rad"][0], b["heading_rad"][at(b, T0_S + STRAIGHT_S)]
        self.assertAlmostEqual(start, s["tf_heading_rad"], delta=1e-3 * start)  # the truth-free start's 5 deg
        # Straight and level, GNSS only: the specific force is vertical, a heading error moves no velocity; the
        # sigma only grows with the gyro offset (0.2 deg/s over 60 s).
        self.assertGreater(end_straight, 0.9 * start)
        # Through the turns the centripetal 3.6 m/s^2 turns a heading error into a velocity error the fixes see:
        # one fix (0.074 m/s) against 3.6 m/s^2 x 1 s is 1.2 deg, about 100 fixes of turning bring it to ~0.1 deg.
        after_turns = b["heading_rad"][at(b, T_TURNS_END_S + 1.0)]
        self.assertLess(after_turns, 0.3 / DEG)
        self.assertGreater(after_turns, 0.01 / DEG)

    def test_after_the_loss_without_aiding_the_attitude_grows_with_the_gyro_bias(self):
        # No magnetometer, no air data: after the loss nothing observes the attitude. Straight and level north
        # (C = I): the body error is phi - delta - tau (E_gyr0 + d_gyr) + the gyro's angle and bias walks, so its
        # covariance is L P_loss L' + (q_white tau + q_walk tau^3 / 3) I with the covariance P_loss at the loss.
        b, s = self.gnss_only, self.gnss_only["figures"]
        p_loss, t_loss = b["p_loss"], b["t_s"][b["k_loss"]]
        for tau in (50.0, 100.0, 150.0):
            k = at(b, t_loss + tau)
            tau = b["t_s"][k] - t_loss
            lmap = np.zeros((3, am.N_STATES))
            lmap[:, am.A_] = np.eye(3)
            lmap[:, am.MT] = -np.eye(3)
            lmap[:, am.BG] = -tau * np.eye(3)
            lmap[:, am.DG] = -tau * np.eye(3)
            walks = s["gyr_white"] ** 2 * tau + s["gyr_walk"] ** 2 * tau ** 3 / 3
            expect = lmap @ p_loss @ lmap.T + np.eye(3) * walks
            np.testing.assert_allclose(b["body"][k], expect, rtol=1e-2, atol=1e-12)
        # ... and the walk is a visible part of it: at 150 s it alone is 0.15 deg per axis.
        self.assertGreater(b["heading_rad"][-1], 3.0 * b["heading_at_loss_rad"])

    def test_air_data_hold_the_tilt_through_gravity(self):
        # With the air data the INS velocity keeps a reference after the loss: a tilt shows as g x tilt in its
        # slope (the wind known from the aided phase, no turbulence here), so the tilt sigma stays where it was at
        # the loss; without them it grows with the gyro bias (previous test).
        for b, factor in ((self.air_no_mag, 1.2), (self.full, 1.2)):
            tilt = np.sqrt(0.5 * (b["tilt_n_rad"] ** 2 + b["tilt_e_rad"] ** 2))
            self.assertLess(tilt[-1], factor * b["tilt_at_loss_rad"])
        tilt = np.sqrt(0.5 * (self.gnss_only["tilt_n_rad"] ** 2 + self.gnss_only["tilt_e_rad"] ** 2))
        self.assertGreater(tilt[-1], 3.0 * self.gnss_only["tilt_at_loss_rad"])

    def test_magnetometer_carries_the_heading_over_the_loss(self):
        # E_mag, B_dev and the soft iron are constant: calibrated in the turns, they keep the heading after the loss.
        b = self.full
        self.assertLess(b["heading_rad"][-1], 1.5 * b["heading_at_loss_rad"])
        self.assertLess(b["heading_rad"][-1], 0.25 * self.air_no_mag["heading_rad"][-1])
        # The metric's window: the mean of E||dr|| over t in [0, t_end].
        win = (b["t_s"] >= -1e-9) & (b["t_s"] <= T_END_S + 1e-9)
        self.assertAlmostEqual(b["mean_window_rad"], float(b["en_rad"][win].mean()), delta=1e-15)

    def test_aligned_start_is_the_alignments_sigma(self):
        # init_mode alignment: the body attitude phi - C delta starts at the alignment's angle sigma, split over
        # three axes, whatever the mounting's own sigma.
        d = write_run(os.path.join(self.tmp.name, "aligned"), init_mode="alignment")
        inp = ai.run_inputs(d, CONFIG)
        s = dict(inp["figures"])
        traj = ai.trajectory(inp["truth"], s)
        s["turb_sigma_mps"] = np.zeros(3)
        p0 = am.initial_covariance(s, traj)
        c0 = traj["c"][0]
        lmap = np.zeros((3, am.N_STATES))
        lmap[:, am.A_] = np.eye(3)
        lmap[:, am.MT] = -c0
        np.testing.assert_allclose(lmap @ p0 @ lmap.T, np.eye(3) * s["align_att_rad"] ** 2 / 3.0, rtol=1e-9, atol=1e-18)
        self.assertGreater(s["mount_rad"], 0.0)


class CommandLine(unittest.TestCase):
    @classmethod
    def setUpClass(cls):
        cls.tmp = tempfile.TemporaryDirectory()
        root = cls.tmp.name
        cls.run_dir = write_run(os.path.join(root, "single"), rot_mean_rad=0.5 / DEG)
        os.makedirs(os.path.join(root, "batch", "runs"))
        write_run(os.path.join(root, "batch", "runs", "run_0000"), rot_mean_rad=0.3 / DEG)
        write_run(os.path.join(root, "batch", "runs", "run_0001"), rot_mean_rad=30.0 / DEG)  # diverged
        write_run(os.path.join(root, "batch", "runs", "run_0002"), rot_mean_rad=0.1 / DEG)

    @classmethod
    def tearDownClass(cls):
        cls.tmp.cleanup()

    def test_run_and_batch(self):
        png = os.path.join(self.tmp.name, "bound.png")
        code, out, err = main_cli("--run", self.run_dir, "--batch", f"b={self.tmp.name}/batch", "--png", png)
        self.assertEqual(code, 0, err)
        lines = out.splitlines()
        bound_line = next(x for x in lines if x.strip().startswith("bound:"))
        filter_line = next(x for x in lines if x.strip().startswith("filter:"))
        mean_deg = float(bound_line.split("over [0, 250] s ")[1].split("°")[0])
        self.assertIn("filter: mean ‖Δr̂‖ 0.500°", filter_line)
        pct = float(filter_line.split("(")[1].split(" %")[0])
        self.assertAlmostEqual(pct, 100.0 * (0.5 / mean_deg - 1.0), delta=0.02 * 100.0 * 0.5 / mean_deg + 1.0)
        # The batch: two runs kept, the diverged one left out; the filters' mean is 0.2 deg.
        row = next(x for x in lines if x.startswith("| b |"))
        cells = [c.strip() for c in row.strip("|").split("|")]
        self.assertEqual(cells[1], "2 (1)")
        self.assertEqual(cells[2], "0.200°")
        # The same truth in every run, so the batch's bound is the single run's.
        self.assertEqual(cells[3], f"{mean_deg:.3f}°")
        # One progress line per run on stderr.
        self.assertEqual(sum(1 for x in err.splitlines() if x.startswith("attitude_bound: b ")), 3)
        with open(png, "rb") as fh:
            self.assertEqual(fh.read(8), b"\x89PNG\r\n\x1a\n")

    def test_runs_limits_the_batch(self):
        code, out, err = main_cli("--batch", f"b={self.tmp.name}/batch", "--runs", "1")
        self.assertEqual(code, 0, err)
        self.assertIn("| b | 1 (0) | 0.300°", out)

    def test_bad_input_is_one_line(self):
        d = self.tmp.name
        nan_run = write_run(os.path.join(d, "nan"), nan_truth=True)
        broken = os.path.join(d, "broken")
        os.makedirs(broken)
        with open(os.path.join(broken, "run.h5"), "w") as fh:
            fh.write("not HDF5")
        cases = [((), "give at least one"),
                 (("--run", os.path.join(d, "missing")), "is not a folder"),
                 (("--batch", "nolabel"), "LABEL=DIR"),
                 (("--batch", f"x={d}"), "no runs/ folder"),
                 (("--run", nan_run), "no reference trajectory"),
                 (("--run", broken), "cannot be read as HDF5"),
                 (("--run", self.run_dir, "--runs", "0"), "--runs must be"),
                 (("--run", self.run_dir, "--magnetometer", "gyro"), "invalid choice"),
                 (("--run", self.run_dir, "--png", os.path.join(d, "no", "such", "f.png")), "does not exist")]
        for args, expect in cases:
            code, out, err = main_cli(*args)
            self.assertEqual(code, 2, args)
            self.assertEqual(len(err.strip().splitlines()), 1, err)
            self.assertTrue(err.startswith("attitude_bound: "), err)
            self.assertIn(expect, err)
            self.assertNotIn("Traceback", err)


if __name__ == "__main__":
    unittest.main()
