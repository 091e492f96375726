"""The ideal filter of attitude_bound.py: the covariance of a linear Kalman filter on the INS error model of a run's
true trajectory, fed with what the run's sensors tell, from the run's t0 to its end (the figures and the truth's
arrays: attitude_bound_inputs.py).

State (47; NED, SI): position (3) and velocity (3) errors; the INS attitude error phi (3, C_est = (I - [phi x]) C,
the frame the inertial sensors measure in); accelerometer and gyro biases, each a run-to-run offset (3) and a drift
(3); magnetometer bias E_mag (3, body), its scale/cross-coupling/soft-iron matrix M (9), the field model's error
B_dev (3, NED); the wind's constant part (N, E) and turbulence (3); the air-data offsets (TAS, AOA, AOS); the
residual IMU mounting delta (3, body: the inertial sensors are compensated with an estimated mounting that is off by
suite.yaml's mounting_estimate_error_deg per angle; the body attitude error, what ||dr_hat|| measures, is
phi - C delta, and the magnetometer and the air data, mounted on the body, see that one).
  d(dp)/dt = dv,   d(dv)/dt = [f_n x] phi + C (E_acc0 + d_acc) + w_acc,   d(phi)/dt = -C (E_gyr0 + d_gyr) + w_gyr
  (f_n = dv/dt - g_n and C from the truth); the drifts and the turbulence first-order Gauss-Markov; the rest
  constant, but the wind's constant part a random walk while the true wind ramps. Phi = I + A dt + (A dt)^2 / 2.
Measurements, at every truth row unless said:
  * GNSS, at the fix epochs t0 + k fix_period_s up to t_GNSS (the sensor's rule, docs/sensors.md; the start's
    position and velocity are the first fix's): position (white sigma N, E and D) and velocity (per axis).
  * Air data, before and after the loss: the ground velocity they give, C v_air + wind, against the INS velocity:
    z = dv + phi_b x v_air_n + dw - C J (b_air + n), v_air from the truth's TAS, AOA, AOS, J its Jacobian with
    respect to them, n their per-sample noise averaged over the samples of a row. This is the specific-force
    observation f = a - g integrated once: its slope is d(dv)/dt + phi x a = phi x g + C E_acc + d(dw)/dt (the
    heading terms of f x phi and phi x a cancel), so the tilt is observed through gravity, limited by the
    accelerometer bias and the wind's acceleration, and the air-data noise enters as a velocity noise instead of a
    differentiated one. The heading enters only through phi x v_air, like a cross wind (the wind triangle: it needs
    a known wind and a known AOS offset).
  * Magnetometer (`vector`, default): B~ = (I + M) C'(B_n - B_dev) + E_mag + n, the sensor's model (docs/sensors.md)
    and the attitude filter's, B_n the model field at the true position: it tells the two attitude components
    across the field, heading and tilt together (the field dips about 70 deg: a tilt error about the horizontal
    field's normal reads as a heading error of tan(dip) = 2.9 times it). `compass`: the compass of heading_bound.py
    (c0 = B_dev across the horizontal field / B_h, c1 cos(yaw) + c2 sin(yaw) = E_mag across it / B_h), i.e. the
    heading row of the same model without its tilt terms. `none`: no magnetometer.
Start at the run's t0 after its navigation's start mode: `alignment` (the paper's runs): the body attitude at the
alignment's angle sigma (split over three axes), the biases at its relative errors of the sensor offsets,
E_mag + M b_b(t0) (the full error it publishes) at its relative error, B_dev at b_dev_rel_error of the run's true
deviation (run.yaml earth_truth); `measurements` (the calibrated scenarios, truth-free): tilt and heading at the
tuning file's sigmas, biases at the sensor offsets, B_dev at the field model's budget. Both: drifts 0 (the walks
start at t0), M and the mounting at their sensor sigmas, position and velocity at the GNSS white sigmas, the
turbulence at its stationary sigma, the wind's constant part at the true airspeed at t0 (no prior: a number not in
config, derived from the truth).
E||x|| of x ~ N(0, P), P the 3x3 attitude covariance, is not sqrt(trace P): with x = r u, r ~ chi_3 independent of
the direction u (uniform on the unit sphere), E||x|| = E[chi_3] E_u sqrt(u'Pu), E[chi_3] = 2 sqrt(2/pi); the sphere
mean is taken on a fixed 1000-point Fibonacci lattice (deterministic; within 2e-5 of the closed forms the unit test
checks: 2 sigma sqrt(2/pi) for P = sigma^2 I, sigma sqrt(2/pi) for rank one, sigma sqrt(pi/2) for rank two).
Simplifications, and which way each moves the bound (meant as a lower bound: what is left out favours the filter):
  favourable (the bound is lower than the truth allows):
  - no scale-factor or cross-coupling errors of the gyros and accelerometers (a gyro cross-coupling of 4.4e-5 makes
    0.016 deg of a 360-deg turn), no lever arm, no GNSS ionospheric walk (the fixes are white);
  - the filter knows the turbulence's and drifts' Gauss-Markov parameters, the linear model about the true
    trajectory, and when the wind ramps; offsets, E_mag, M, B_dev and the mounting are constant and known to be;
  - Earth rate, transport rate, Schuler and gravity-model errors left out; the gravity direction is exact;
  - no linearisation error (a truth-free start of several degrees is treated as small).
  pessimistic (higher than an ideal filter could reach): the barometer is not used (the vertical channel says little
  of the attitude).
  neutral: the bias drifts and the turbulence as Gauss-Markov processes of matching moments; the turbulence per NED
  axis (the physics' Dryden gusts are per body axis, with nearly equal sigmas).
Not modelled: the run's faults (GNSS outages that end, spoofed fixes), a GNSS that is never lost.
"""
import math

import numpy as np

import attitude_bound_inputs as ai

# State layout (see the docstring).
P_, V_, A_ = slice(0, 3), slice(3, 6), slice(6, 9)
BA, DA, BG, DG = slice(9, 12), slice(12, 15), slice(15, 18), slice(18, 21)
EM, BD, WC, WT, AB = slice(21, 24), slice(24, 27), slice(27, 29), slice(29, 32), slice(32, 35)
MT, MM = slice(35, 38), slice(38, 47)
N_STATES = 47
CHUNK = 512  # rows per block of vectorised transition and measurement matrices
E_CHI3 = 2.0 * math.sqrt(2.0 / math.pi)


def skew(v):
    """[v x] for an array of 3-vectors (..., 3) -> (..., 3, 3)."""
    s = np.zeros(v.shape[:-1] + (3, 3))
    s[..., 0, 1], s[..., 0, 2] = -v[..., 2], v[..., 1]
    s[..., 1, 0], s[..., 1, 2] = v[..., 2], -v[..., 0]
    s[..., 2, 0], s[..., 2, 1] = -v[..., 1], v[..., 0]
    return s


def initial_covariance(s, traj):
    """P0 at the run's t0 after its navigation start mode (see the docstring)."""
    p = np.zeros(N_STATES)
    p[P_] = [s["pos_m"] ** 2, s["pos_m"] ** 2, s["pos_v_m"] ** 2]
    p[V_] = s["vel_mps"] ** 2
    if s["init_mode"] == "alignment":
        p[A_] = s["align_att_rad"] ** 2 / 3.0
        p[BA] = (s["align_acc_rel"] * s["acc_offset"]) ** 2
        p[BG] = (s["align_gyr_rel"] * s["gyr_offset"]) ** 2
        p[EM] = (s["align_mag_rel"] * s["mag_body_nT"]) ** 2
        b_dev = s["bdev_true_nT"] if s["bdev_true_nT"] is not None else s["bdev_budget_nT"]
        p[BD] = (s["align_bdev_rel"] * b_dev) ** 2
    else:
        p[A_] = [s["tf_tilt_rad"] ** 2, s["tf_tilt_rad"] ** 2, s["tf_heading_rad"] ** 2]
        p[BA] = s["acc_offset"] ** 2
        p[BG] = s["gyr_offset"] ** 2
        p[EM] = s["mag_body_nT"] ** 2
        p[BD] = s["bdev_budget_nT"] ** 2
    p[WC] = float(np.linalg.norm(traj["v_air_n_mps"][0])) ** 2
    p[WT] = s["turb_sigma_mps"] ** 2
    p[AB] = [s["tas_offset_mps"] ** 2, s["aoa_offset_rad"] ** 2, s["aos_offset_rad"] ** 2]
    p[MT] = s["mount_rad"] ** 2
    p[MM] = np.where(np.eye(3).ravel() > 0, s["mag_scale"], s["mag_cross"]) ** 2
    p = np.diag(p)
    # The start's sigmas are of the body attitude phi - C delta: phi = phi_body + C delta, delta independent.
    c0 = traj["c"][0]
    p[A_, A_] += c0 @ p[MT, MT] @ c0.T
    p[A_, MT] = c0 @ p[MT, MT]
    p[MT, A_] = p[A_, MT].T
    if s["init_mode"] == "alignment":
        # The alignment gives the magnetometer's full error at t0, E_mag + M b_b(t0): E_mag = that - M b_b(t0).
        h0 = mag_matrix_rows(c0.T @ traj["b_n_nT"][0])
        p[EM, EM] += h0 @ p[MM, MM] @ h0.T
        p[EM, MM] = -h0 @ p[MM, MM]
        p[MM, EM] = p[EM, MM].T
    return p


def mag_matrix_rows(b_b):
    """d(M b)/d vec(M) of field vectors b_b (..., 3), M stored row by row: (..., 3, 9)."""
    h = np.zeros(b_b.shape[:-1] + (3, 9))
    for i in range(3):
        h[..., i, 3 * i:3 * i + 3] = b_b
    return h


# The rows of Phi that differ from the identity (the states with dynamics) and the columns they reach.
DYN = np.r_[P_, V_, A_, DA, DG, WT]
REACH = np.r_[P_, V_, A_, BA, DA, BG, DG, WT]


def transition_block(traj, s, k0, k1):
    """Phi = I + A dt + (A dt)^2 / 2 for the steps from rows k0..k1-1 to the next row: its rows DYN, columns REACH,
    (k1-k0, 18, 24); every other row of Phi is the identity's."""
    m = k1 - k0
    c, dt = traj["c"][k0:k1], traj["dt_s"][k0:k1]
    a = np.zeros((m, N_STATES, N_STATES))
    a[:, P_, V_] = np.eye(3)
    a[:, V_, A_] = skew(traj["f_n_mps2"][k0:k1])
    a[:, V_, BA] = c
    a[:, V_, DA] = c
    a[:, A_, BG] = -c
    a[:, A_, DG] = -c
    i3 = np.eye(3)
    a[:, DA, DA] = -i3 / s["drift_tau_s"]
    a[:, DG, DG] = -i3 / s["drift_tau_s"]
    a[:, WT, WT] = -i3 / s["turb_tau_s"]
    ad = a[:, :, REACH] * dt[:, None, None]
    # Contiguous copies: a stack gathered by an index array is laid out index-major, which matmul handles slowly.
    rows, reach = np.ascontiguousarray(ad[:, DYN]), np.ascontiguousarray(ad[:, REACH])
    return np.eye(N_STATES)[DYN][:, REACH] + rows + 0.5 * np.matmul(rows, reach)


def measurement_block(traj, s, k0, k1, magnetometer, air_data):
    """The air-data and magnetometer rows of rows k0..k1-1 (see the docstring), vectorised: H (m, r, n), R (m, r, r)."""
    m = k1 - k0
    c, b_n = traj["c"][k0:k1], traj["b_n_nT"][k0:k1]
    ct = np.transpose(c, (0, 2, 1))
    row_s = traj["row_s"][k0:k1]
    hs, rs = [], []
    if air_data:
        h = np.zeros((m, 3, N_STATES))
        h_att = -skew(traj["v_air_n_mps"][k0:k1])
        cj = np.matmul(c, traj["jac"][k0:k1])
        h[:, :, V_] = np.eye(3)
        h[:, :, A_] = h_att
        h[:, :, WC] = np.eye(3)[:, :2]
        h[:, :, WT] = np.eye(3)
        h[:, :, AB] = -cj
        h[:, :, MT] = -np.matmul(h_att, c)
        white = np.array([s["tas_white_mps"], s["aoa_white_rad"], s["aos_white_rad"]]) ** 2
        # A per-sample white noise averaged over the sensor samples of a row.
        r = np.matmul(cj * white[None, None, :], np.transpose(cj, (0, 2, 1))) * (s["sample_s"] / row_s)[:, None, None]
        hs.append(h)
        rs.append(r)
    if magnetometer != "none":
        h = np.zeros((m, 3, N_STATES))
        h_att = np.matmul(ct, skew(b_n))
        b_b = np.einsum("kij,kj->ki", ct, b_n)
        h[:, :, A_] = h_att
        h[:, :, EM] = np.eye(3)
        h[:, :, BD] = -ct
        h[:, :, MT] = -np.matmul(h_att, c)
        h[:, :, MM] = mag_matrix_rows(b_b)
        r = np.eye(3)[None] * (s["mag_white_nT"] ** 2 / row_s)[:, None, None]
        if magnetometer == "compass":
            # The heading row of the vector model without its tilt terms: the NED residual C z projected on the
            # horizontal unit normal of the field, over B_h.
            b_h2 = b_n[:, 0] ** 2 + b_n[:, 1] ** 2
            u = np.stack([-b_n[:, 1], b_n[:, 0], np.zeros(m)], 1) / b_h2[:, None]
            h = np.einsum("ki,kij,kjn->kn", u, c, h)[:, None, :]
            h[:, 0, A_] = [0.0, 0.0, -1.0]
            h[:, 0, MT] = -np.matmul(h[:, :, A_], c)[:, 0]
            r = (s["mag_white_nT"] ** 2 / row_s / b_h2)[:, None, None]
        hs.append(h)
        rs.append(r)
    if not hs:
        return None, None
    h = np.concatenate(hs, axis=1)
    r = np.zeros((m, h.shape[1], h.shape[1]))
    i = 0
    for blk in rs:
        r[:, i:i + blk.shape[1], i:i + blk.shape[1]] = blk
        i += blk.shape[1]
    return h, r


def covariance_run(traj, s, p0, t_gnss, magnetometer="vector", air_data=True):
    """The Kalman covariance over the rows of TRAJ. Returns the covariance of the body attitude error phi - C delta
    at each row (K, 3, 3), the full covariance at the row of the GNSS loss and the index of that row."""
    t, dt = traj["t_s"], traj["dt_s"]
    k_rows = len(t)
    traj["row_s"] = np.append(dt, dt[-1])
    # Process noise densities (per second).
    q = np.zeros(N_STATES)
    q[V_] = s["acc_white"] ** 2
    q[A_] = s["gyr_white"] ** 2
    if s["band"] > 0.0:  # band 0: no drift
        q[DA] = s["acc_walk"] ** 2
        q[DG] = s["gyr_walk"] ** 2
    q[WT] = 2.0 * s["turb_sigma_mps"] ** 2 / s["turb_tau_s"]
    qd_all = q[None, :] * dt[:, None]
    qd_all[:, WC] = traj["q_wind_m2ps3"] * dt[:, None]
    phase = (t - t[0]) / s["fix_s"]
    is_fix = (np.abs(phase - np.round(phase)) * s["fix_s"] < 0.5 * traj["row_s"]) & (t <= t_gnss + 1e-9)
    is_fix[0] = False  # the start's position and velocity are the first fix's
    k_loss = int(np.searchsorted(t, t_gnss - 1e-9))
    h_gnss = np.eye(6, N_STATES)
    r_gnss = np.diag([s["pos_m"] ** 2, s["pos_m"] ** 2, s["pos_v_m"] ** 2] + [s["vel_mps"] ** 2] * 3)
    keep = np.r_[A_, MT]
    blocks = np.empty((k_rows, 6, 6))
    diag = np.diag_indices(N_STATES)
    p = p0.copy()
    p_loss = None
    for k0 in range(0, k_rows, CHUNK):
        k1 = min(k0 + CHUNK, k_rows)
        # phi[j]: the step into row k0 + j (row 0 has none, a placeholder keeps the indices).
        phi = transition_block(traj, s, k0 - 1, k1 - 1) if k0 > 0 else \
            np.concatenate([np.zeros((1, len(DYN), len(REACH))), transition_block(traj, s, 0, k1 - 1)])
        h_blk, r_blk = measurement_block(traj, s, k0, k1, magnetometer, air_data)
        for k in range(k0, k1):
            j = k - k0
            if k > 0:
                x = p.copy()
                x[DYN] = phi[j] @ p[REACH]
                p = x.copy()
                p[:, DYN] = x[:, REACH] @ phi[j].T
                p[diag] += qd_all[k - 1]
            h, r = (h_blk[j], r_blk[j]) if h_blk is not None else (None, None)
            if is_fix[k]:
                h = h_gnss if h is None else np.vstack([h, h_gnss])
                r = r_gnss if r is None else np.block([[r, np.zeros((len(r), 6))], [np.zeros((6, len(r))), r_gnss]])
            if h is not None:
                hp = h @ p
                p = p - hp.T @ (np.linalg.inv(hp @ h.T + r) @ hp)
                if k % 16 == 0:  # the update's round-off slowly breaks the symmetry
                    p = 0.5 * (p + p.T)
            if k == k_loss:
                p_loss = p.copy()
            blocks[k] = p[np.ix_(keep, keep)]
    # The body attitude error phi - C delta: [I, -C] blocks [I, -C]'.
    t_map = np.concatenate([np.broadcast_to(np.eye(3), (k_rows, 3, 3)), -traj["c"]], axis=2)
    body = np.matmul(np.matmul(t_map, blocks), np.transpose(t_map, (0, 2, 1)))
    return 0.5 * (body + np.transpose(body, (0, 2, 1))), p_loss, k_loss


def fibonacci_sphere(n=1000):
    """N points spread evenly over the unit sphere (a Fibonacci lattice), (N, 3)."""
    i = np.arange(n) + 0.5
    z = 1.0 - 2.0 * i / n
    r = np.sqrt(1.0 - z * z)
    az = math.pi * (1.0 + math.sqrt(5.0)) * i
    return np.stack([r * np.cos(az), r * np.sin(az), z], 1)


_SPHERE = fibonacci_sphere()
_SPHERE_PAIRS = np.stack([_SPHERE[:, 0] ** 2, _SPHERE[:, 1] ** 2, _SPHERE[:, 2] ** 2, 2 * _SPHERE[:, 0] * _SPHERE[:, 1],
                          2 * _SPHERE[:, 0] * _SPHERE[:, 2], 2 * _SPHERE[:, 1] * _SPHERE[:, 2]], 1)


def expected_norm(cov):
    """E||x|| for x ~ N(0, cov), cov (K, 3, 3) -> (K,): E[chi_3] times the sphere mean of sqrt(u' cov u)."""
    out = np.empty(len(cov))
    for k0 in range(0, len(cov), 4096):
        c = cov[k0:k0 + 4096]
        six = np.stack([c[:, 0, 0], c[:, 1, 1], c[:, 2, 2], c[:, 0, 1], c[:, 0, 2], c[:, 1, 2]], 1)
        quad = np.maximum(six @ _SPHERE_PAIRS.T, 0.0)
        out[k0:k0 + 4096] = E_CHI3 * np.sqrt(quad).mean(axis=1)
    return out


def run_bound(inp, magnetometer="vector", air_data=True):
    """The bound over one run: per-row times and sigmas, E||dr||, and the figures at the loss and over the window."""
    s = dict(inp["figures"])
    traj = ai.trajectory(inp["truth"], s)
    sig_t, tau_t, q_wind = ai.wind_models(traj)
    traj["q_wind_m2ps3"] = q_wind
    s["turb_sigma_mps"], s["turb_tau_s"] = sig_t, tau_t
    p0 = initial_covariance(s, traj)
    body, p_loss, k_loss = covariance_run(traj, s, p0, inp["t_gnss_s"], magnetometer, air_data)
    en = expected_norm(body)
    t = traj["t_s"]
    win = (t >= inp["t_start_s"] - 1e-9) & (t <= inp["t_end_s"] + 1e-9)
    after = win & (t > inp["t_gnss_s"] + 1e-9)
    return {"t_s": t, "tilt_n_rad": np.sqrt(body[:, 0, 0]), "tilt_e_rad": np.sqrt(body[:, 1, 1]),
            "heading_rad": np.sqrt(body[:, 2, 2]), "en_rad": en, "rms_rad": np.sqrt(np.trace(body, axis1=1, axis2=2)),
            "mean_window_rad": float(en[win].mean()),
            "mean_after_rad": float(en[after].mean()) if after.any() else math.nan,
            "heading_at_loss_rad": float(np.sqrt(body[k_loss, 2, 2])),
            "tilt_at_loss_rad": float(np.sqrt(0.5 * (body[k_loss, 0, 0] + body[k_loss, 1, 1]))),
            "k_loss": k_loss, "p_loss": p_loss, "body": body, "figures": s, "t_gnss_s": inp["t_gnss_s"],
            "window_s": (inp["t_start_s"], inp["t_end_s"])}
