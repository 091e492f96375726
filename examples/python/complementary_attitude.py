#!/usr/bin/python3
"""A Python attitude filter that replaces gdnav's nav_att: a Mahony-style complementary filter (docs/python.md).

    gdnav run --scenario paper2 --seed 1 --layout distributed --external nav_att --domain 7 --out out/py
    PYTHONPATH=build/python /usr/bin/python3 examples/python/complementary_attitude.py --domain 7

or inside the gdnav process (any layout, also direct; docs/python.md, "In-process members"):

    gdnav run --scenario paper2 --seed 1 --layout direct --out out/py \
        --set 'run.members={nav_att: {python: {file: examples/python/complementary_attitude.py, class: ComplementaryAttitude}}}'

Inputs: ImuSample, MagSample, AirDataEstimate (step k) and PositionEstimate (step k-1, for the Earth rate and the
transport rate). Output: AttitudeEstimate (q_nb, euler_rad, w_nb_b_rps, gyr_bias_rps, att_sigma_rad; the magnetic
states of the built-in EKF stay zero).

The attitude q_nb (body -> NED) is propagated with the gyro rate minus the estimated bias and minus the rotation of
NED (Earth rate + transport rate), and pulled towards two vector observations through a PI correction of the rate:
  - tilt: gravity in body axes from the accelerometer, g_b = w x v_b + dv_b/dt - f_b, with the air-relative
    velocity v_b = TAS [cos a cos b, sin b, sin a cos b] (the wind is steady over a few seconds, so the air-relative
    velocity carries the aircraft's acceleration); compared with the estimated down axis;
  - heading: the horizontal magnetic field rotated to NED with the estimate, compared with the reference field,
    which is the first magnetometer sample rotated by the aligned attitude (the flight area is small). Only the
    heading axis is corrected from the magnetometer, so magnetic errors never tilt the estimate.
It starts from the pre-flight alignment carried by the samples (attitude, gyro, accelerometer and magnetometer
errors at t0).
"""
import math
import sys

import numpy as np

import gdnav_client as g

DT_S = 0.01
G_MPS2 = 9.80665
W_IE_RPS = 7.292115e-5
R_EARTH_M = 6.371e6

# Gains. The correction is a PI loop on the attitude error; its proportional gain sets the time constant over which
# the gyro is trusted against the vector observations: 1 / 0.05 = 20 s. The gyro, started with the bias of the
# alignment, drifts slowly, while the tilt observation is disturbed at every step by turbulence and by the errors
# of the compensated acceleration (noise of the angle-of-attack and sideslip vanes and of the airspeed, scaled by
# the centripetal acceleration of the turns); a 20-s average removes most of those. Much smaller gains let the
# gyro error grow; much larger ones pass the gust accelerations into the attitude. The integral gains are
# KP^2 / 4: a critically damped loop (no overshoot after the turns) whose bias estimate settles in about
# 2 / KP = 40 s. The heading loop uses the same gains (the magnetometer noise relative to the field is of the same
# order). Measured with this tuning in scenario #2, seed 1: mean attitude error 0.16 deg (docs/python.md).
KP_TILT, KI_TILT = 0.05, 0.05**2 / 4
KP_HEAD, KI_HEAD = 0.05, 0.05**2 / 4
# Tilt observations whose gravity magnitude is off by more than this are skipped (unmodelled manoeuvre or a gust).
G_GATE_MPS2 = 1.5
# Reported 1-sigma (about N, E, D): not a propagated covariance; the accuracy this tuning reaches in scenario #2.
SIGMA_TILT_RAD, SIGMA_HEAD_RAD = math.radians(0.3), math.radians(0.6)


def quat_to_dcm(q):
    """R_nb of a unit quaternion (w, x, y, z) as three row tuples: rotates body components into NED."""
    w, x, y, z = q
    return ((1 - 2 * (y * y + z * z), 2 * (x * y - w * z), 2 * (x * z + w * y)),
            (2 * (x * y + w * z), 1 - 2 * (x * x + z * z), 2 * (y * z - w * x)),
            (2 * (x * z - w * y), 2 * (y * z + w * x), 1 - 2 * (x * x + y * y)))


# Per-step work is on 3-vectors: plain floats cost a fraction of numpy's per-call overhead (about 1 us per small
# array operation), so numpy is used for the samples in and the estimates out, and the arithmetic is inline.
def cross(a, b):
    return (a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0])


def mul(R, v):
    return tuple(r[0] * v[0] + r[1] * v[1] + r[2] * v[2] for r in R)


def mul_t(R, v):
    return tuple(R[0][i] * v[0] + R[1][i] * v[1] + R[2][i] * v[2] for i in range(3))


class ComplementaryFilter:
    def __init__(self):
        self.q = None                  # q_nb (w, x, y, z)
        self.bias = [0.0, 0.0, 0.0]    # gyro error [rad/s]
        self.acc_err = (0.0, 0.0, 0.0) # accelerometer error from the alignment [m/s2]
        self.mag_err = (0.0, 0.0, 0.0) # magnetometer error from the calibration [nT]
        self.ref_h = None              # reference horizontal magnetic field direction in NED (unit 2-vector)
        self.w_in_n = (0.0, 0.0, 0.0)  # rotation of NED w.r.t. inertial space, in NED [rad/s]

    def initialise(self, imu, mag):
        q = imu["align_q_nb"]
        self.q = (q / np.linalg.norm(q)).tolist()
        self.bias = imu["align_gyr_err_rps"].tolist()
        self.acc_err = imu["align_acc_err_mps2"].tolist()
        self.mag_err = mag["align_mag_err_nT"].tolist()
        m_n = mul(quat_to_dcm(self.q), (mag["b_b_nT"] - self.mag_err).tolist())
        h = math.hypot(m_n[0], m_n[1])
        self.ref_h = (m_n[0] / h, m_n[1] / h)

    def set_navigation_frame_rate(self, lat, h, v_n):
        r = R_EARTH_M + h
        self.w_in_n = (W_IE_RPS * math.cos(lat) + v_n[1] / r, -v_n[0] / r,
                       -W_IE_RPS * math.sin(lat) - v_n[1] * math.tan(lat) / r)

    def step(self, w_ib_b, f_b, air, m_b):
        """One step: gyro and accelerometer samples, air data (tas, aoa, aos, tas_dot) or None, magnetometer sample
        or None (sequences of floats). Returns the estimated body rate relative to NED, w_nb_b."""
        R = quat_to_dcm(self.q)
        down_b = R[2]                                   # NED down axis in body components (R_bn e_z)
        w_in_b = mul_t(R, self.w_in_n)
        w_nb_b = [w_ib_b[i] - self.bias[i] - w_in_b[i] for i in range(3)]
        corr = [0.0, 0.0, 0.0]
        if air is not None:
            tas, aoa, aos, tas_dot = air
            ca, cb = math.cos(aoa), math.cos(aos)
            u = (ca * cb, math.sin(aos), math.sin(aoa) * cb)
            wxu = cross(w_nb_b, u)
            g_b = [tas * wxu[i] + tas_dot * u[i] - (f_b[i] - self.acc_err[i]) for i in range(3)]
            n = math.sqrt(g_b[0] ** 2 + g_b[1] ** 2 + g_b[2] ** 2)
            if abs(n - G_MPS2) < G_GATE_MPS2:
                e = cross([c / n for c in g_b], down_b)  # measured x estimated: rotates the estimate towards it
                for i in range(3):
                    corr[i] += KP_TILT * e[i]
                    self.bias[i] -= KI_TILT * DT_S * e[i]
        if m_b is not None:
            m_n = mul(R, [m_b[i] - self.mag_err[i] for i in range(3)])
            hn = math.hypot(m_n[0], m_n[1])
            if hn > 0.0:
                s = (m_n[0] * self.ref_h[1] - m_n[1] * self.ref_h[0]) / hn  # sin of the heading error
                for i in range(3):
                    corr[i] += KP_HEAD * s * down_b[i]
                    self.bias[i] -= KI_HEAD * DT_S * s * down_b[i]
        # Quaternion integration of the corrected rate over one step (exact for a constant rate).
        th = [(w_nb_b[i] + corr[i]) * DT_S for i in range(3)]
        a = math.sqrt(th[0] ** 2 + th[1] ** 2 + th[2] ** 2)
        if a > 0.0:
            sa = math.sin(0.5 * a) / a
            c, x1, y1, z1 = math.cos(0.5 * a), th[0] * sa, th[1] * sa, th[2] * sa
            w0, x0, y0, z0 = self.q
            q = (w0 * c - x0 * x1 - y0 * y1 - z0 * z1, w0 * x1 + x0 * c + y0 * z1 - z0 * y1,
                 w0 * y1 - x0 * z1 + y0 * c + z0 * x1, w0 * z1 + x0 * y1 - y0 * x1 + z0 * c)
            nq = math.sqrt(q[0] ** 2 + q[1] ** 2 + q[2] ** 2 + q[3] ** 2)
            self.q = [v / nq for v in q]
        return w_nb_b


class ComplementaryAttitude:
    """The member class (docs/python.md, "Member classes"): ports declared in the constructor, step(k, t_s) every
    step. main() runs it as an external member; gdnav runs it in process with
    --set 'run.members={nav_att: {python: {file: examples/python/complementary_attitude.py,
    class: ComplementaryAttitude}}}'."""

    def __init__(self, m):
        self.m = m
        self.imu = m.input("gdnav/ImuSample")
        self.mag = m.input("gdnav/MagSample")
        self.air = m.input("gdnav/AirDataEstimate")
        self.pos = m.input("gdnav/PositionEstimate", lag=g.Lag.Previous)
        self.att = m.output("gdnav/AttitudeEstimate")
        self.f = ComplementaryFilter()
        self.att["att_sigma_rad"] = np.array([SIGMA_TILT_RAD, SIGMA_TILT_RAD, SIGMA_HEAD_RAD])

    def step(self, k, t_s):
        imu, mag, air, pos, att, f = self.imu, self.mag, self.air, self.pos, self.att, self.f
        if not imu.available():
            return                                      # hold the last estimate
        if f.q is None:
            if not mag.available() or not imu["align_q_nb"].any():
                return                                  # nothing published until the alignment is there
            f.initialise(imu, mag)
            self.m.publish_status("initialised from the pre-flight alignment")
        if pos.available():
            f.set_navigation_frame_rate(pos["lat_rad"], pos["h_m"], pos["v_n_mps"].tolist())
        a = (air["tas_mps"], air["aoa_rad"], air["aos_rad"], air["tas_dot_mps2"]) if air.available() else None
        w_nb_b = f.step(imu["w_b_rps"].tolist(), imu["f_b_mps2"].tolist(), a,
                        mag["b_b_nT"].tolist() if mag.available() else None)
        R = quat_to_dcm(f.q)
        att["q_nb"] = np.array(f.q)
        att["euler_rad"] = np.array([math.atan2(R[1][0], R[0][0]), -math.asin(max(-1.0, min(1.0, R[2][0]))),
                                     math.atan2(R[2][1], R[2][2])])
        att["w_nb_b_rps"] = np.array(w_nb_b)
        att["gyr_bias_rps"] = np.array(f.bias)


def main(argv):
    m = g.Member.from_args(argv, "nav_att")
    member = ComplementaryAttitude(m)
    m.on_step(member.step)
    code = m.run()
    cost = m.step_cost
    print(f"complementary_attitude: exit code {code}; Python step cost over {cost['steps']} steps: CPU mean "
          f"{cost['cpu_mean_us']:.1f} us, max {cost['cpu_max_us']:.1f} us; wall mean {cost['mean_us']:.1f} us, max "
          f"{cost['max_us']:.1f} us", flush=True)
    return code


if __name__ == "__main__":
    sys.exit(main(sys.argv))
