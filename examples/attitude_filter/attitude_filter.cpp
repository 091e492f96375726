// An external attitude filter of the user's own design — a Mahony-style complementary filter (gyro propagation,
// PI correction of tilt by the accelerometer and of heading by the magnetometer) — that replaces gdnav's `nav_att`
// (an EKF) in a run. Only the public client API, the IDL message types and gdnav's rotation toolkit are used:
//
//   gdnav run --scenario paper2 --seed 1 --layout distributed --external nav_att --domain 7 --out out/ext
//   gdnav-example-attitude --domain 7
//
// Equations (README.md): q_nb Hamilton body->NED, R = R(q_nb), b = gyro bias estimate, dt from StepInfo.
//   w_nb   = w~ - b - R^T (w_ie + w_en)                               (w_ie, w_en from the PositionEstimate of k-1)
//   g_b    = w_nb x v_b + V' u_b - (f~ - E_acc0),  v_b = V u_b,  u_b = (cos a cos b, sin b, sin a cos b)
//   e_acc  = (g_b / |g_b|) x (R^T d),  d = (0, 0, 1)                   tilt error, body axes
//   e_mag  = -R^T d * wrap(psi(R (m~ - E_mag0)) - psi(B_ref_n))       heading error only, psi = atan2 of N/E parts
//            B_ref_n = mean of R (m~ - E_mag0) over 30-40 s after the start (heading loop off until then)
//   e      = kp_acc e_acc + kp_mag e_mag;  q <- q (x) exp((w_nb + e) dt);  b <- b - (ki_acc e_acc + ki_mag e_mag) dt
#include <array>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <exception>
#include <string>

#include <gdnav/client/member.hpp>
#include <spdlog/spdlog.h>

#include "math/rotation.hpp"
#include "framework/msg_eigen.hpp"

namespace gc = gdnav::client;
namespace msg = gdnav::msg;
namespace gm = gdnav::math;
using gdnav::runtime::to_array;
using gdnav::runtime::to_quat;
using gdnav::runtime::to_vec3;

namespace {

// Gains [rad/s per rad of error]. The corrections act as first-order loops with time constant 1/kp; the integral
// gains give each loop critical damping (ki = kp^2 / 4). Tilt: 20 s averages out the gust accelerations that the
// air-relative centripetal compensation cannot see (turbulence lasts seconds) while the MEMS gyro (ADIS16488A:
// 0.0043 deg/sqrt(s) noise, bias walk 1.4e-4 deg/s^1.5) drifts < 0.01 deg in that time. Heading: the magnetometer
// is clean (50 nT noise on ~50 uT, soft iron ~0.1 %), so a faster 10 s loop costs little noise.
constexpr double kKpAcc = 0.05, kKiAcc = kKpAcc * kKpAcc / 4.0;
constexpr double kKpMag = 0.10, kKiMag = kKpMag * kKpMag / 4.0;
constexpr double kGravity = 9.80665;       // only to reject accelerometer samples far from 1 g (manoeuvres)
// B_ref_n = mean of R m~ over [30 s, 40 s) after the initialisation, when the tilt loop has settled: the vertical
// field (~3x the horizontal one here) turns any tilt error of R into a heading error of the reference (0.1 deg of
// alignment tilt error -> 0.3 deg), while the gyro alone keeps the heading within ~0.1 deg for those 40 s.
constexpr double kMagRefFrom_s = 30.0, kMagRefTo_s = 40.0;
constexpr double kResidualTau_s = 20.0;    // att_sigma_rad: running RMS of the correction residuals
constexpr double kEarthRate = 7.292115e-5; // [rad/s]
constexpr double kEarthRadius = 6378137.0; // [m], spherical Earth for the transport rate

double heading(const gm::Vec3& v_n) { return std::atan2(v_n.y(), v_n.x()); }

}  // namespace

int main(int argc, char** argv) try {
    gc::Member m(gc::Options::from_args(argc, argv, "nav_att"));
    const auto& imu = m.input<msg::ImuSample>("gdnav/ImuSample");
    const auto& mag = m.input<msg::MagSample>("gdnav/MagSample");
    const auto& air = m.input<msg::AirDataEstimate>("gdnav/AirDataEstimate");
    const auto& pos = m.input<msg::PositionEstimate>("gdnav/PositionEstimate", gc::Lag::Previous);
    auto& out = m.output<msg::AttitudeEstimate>("gdnav/AttitudeEstimate");

    bool initialized = false;
    gm::Quat q = gm::Quat::Identity();
    gm::Vec3 bias = gm::Vec3::Zero(), acc_err = gm::Vec3::Zero(), mag_err = gm::Vec3::Zero();
    gm::Vec3 b_ref_n = gm::Vec3::Zero(), res_var = gm::Vec3::Zero();
    int mag_ref_count = 0;
    std::uint64_t steps = 0, acc_rejected = 0;
    double t_init = 0.0;

    m.on_step([&](const gc::StepInfo& s) {
        if (!imu.available() || !mag.available()) return;  // a lost sensor: hold the last estimate
        const msg::ImuSample& i = imu.get();
        if (!initialized) {  // pre-flight alignment published with the samples (all zero = none)
            if (i.align_q_nb()[0] == 0.0 && i.align_q_nb()[1] == 0.0 && i.align_q_nb()[2] == 0.0) return;
            q = to_quat(i.align_q_nb()).normalized();
            bias = to_vec3(i.align_gyr_err_rps());
            acc_err = to_vec3(i.align_acc_err_mps2());
            mag_err = to_vec3(mag.get().align_mag_err_nT());
            initialized = true;
            t_init = s.t_s;
            m.publish_status("complementary filter initialised from the alignment at t = " + std::to_string(s.t_s));
        }
        ++steps;
        const gm::Mat3 r = q.toRotationMatrix();
        // Earth and transport rate at the position of step k-1 (nav_pos publishes zeros until its first fix).
        gm::Vec3 w_in_n = gm::Vec3::Zero();
        if (pos.available() && (pos.get().lat_rad() != 0.0 || pos.get().lon_rad() != 0.0)) {
            const double lat = pos.get().lat_rad(), rh = kEarthRadius + pos.get().h_m();
            const gm::Vec3 v = to_vec3(pos.get().v_n_mps());
            w_in_n = gm::Vec3(kEarthRate * std::cos(lat), 0.0, -kEarthRate * std::sin(lat)) +
                     gm::Vec3(v.y() / rh, -v.x() / rh, -v.y() * std::tan(lat) / rh);
        }
        const gm::Vec3 w_nb = to_vec3(i.w_b_rps()) - bias - r.transpose() * w_in_n;
        const gm::Vec3 down_b = r.transpose() * gm::Vec3::UnitZ();  // estimated NED down in body axes

        // Tilt: gravity = inertial acceleration - specific force, the acceleration from the air-relative velocity.
        gm::Vec3 e_acc = gm::Vec3::Zero();
        if (air.available() && air.get().tas_mps() > 1.0) {
            const auto& a = air.get();
            const gm::Vec3 u = gm::vtas_body(1.0, a.aoa_rad(), a.aos_rad());
            const gm::Vec3 g_b = w_nb.cross(a.tas_mps() * u) + a.tas_dot_mps2() * u - (to_vec3(i.f_b_mps2()) - acc_err);
            if (std::fabs(g_b.norm() - kGravity) < 0.2 * kGravity) e_acc = g_b.normalized().cross(down_b);
            else ++acc_rejected;
        }
        // Heading: compare the horizontal direction of the measured field in N with the reference.
        const gm::Vec3 m_n = r * (to_vec3(mag.get().b_b_nT()) - mag_err);
        gm::Vec3 e_mag = gm::Vec3::Zero();
        double dpsi = 0.0;
        if (s.t_s - t_init < kMagRefTo_s) {  // heading on the gyro alone meanwhile
            if (s.t_s - t_init >= kMagRefFrom_s) b_ref_n += (m_n - b_ref_n) / static_cast<double>(++mag_ref_count);
        } else {
            dpsi = gm::wrap_pi(heading(m_n) - heading(b_ref_n));
            e_mag = -dpsi * down_b;
        }

        const gm::Vec3 e = kKpAcc * e_acc + kKpMag * e_mag;
        bias -= (kKiAcc * e_acc + kKiMag * e_mag) * s.dt_s;
        q = (q * gm::quat_from_rotv((w_nb + e) * s.dt_s)).normalized();

        // Residual RMS about N axes (tilt: north/east, heading: down) — an indicator of the sensors' disagreement,
        // not a covariance: a complementary filter has none.
        const gm::Vec3 res_n = r * e_acc + gm::Vec3(0.0, 0.0, dpsi);
        res_var += (res_n.cwiseProduct(res_n) - res_var) * (s.dt_s / kResidualTau_s);

        msg::AttitudeEstimate& o = out.value();
        o.q_nb(to_array(q));
        const gm::Euler eu = gm::euler_from_quat(q);
        o.euler_rad(std::array<double, 3>{eu.yaw_rad, eu.pitch_rad, eu.bank_rad});
        o.w_nb_b_rps(to_array(w_nb));
        o.gyr_bias_rps(to_array(bias));
        o.mag_bias_nT(to_array(mag_err));  // the alignment's magnetometer error, used as is
        o.att_sigma_rad(to_array(gm::Vec3(res_var.cwiseSqrt())));
    });

    m.on_finish([&](bool completed) {
        const gm::Euler eu = gm::euler_from_quat(q);
        spdlog::info("complementary filter: {} ({} steps from t = {:.2f} s, {} accelerometer samples rejected)",
                     completed ? "run completed" : "run NOT completed", steps, t_init, acc_rejected);
        spdlog::info("final yaw/pitch/bank {:.2f}/{:.2f}/{:.2f} deg; gyro bias [{:.4f} {:.4f} {:.4f}] deg/s; "
                     "B_ref_n [{:.0f} {:.0f} {:.0f}] nT; residual RMS N/E/D [{:.3f} {:.3f} {:.3f}] deg",
                     gm::rad2deg(eu.yaw_rad), gm::rad2deg(eu.pitch_rad), gm::rad2deg(eu.bank_rad),
                     gm::rad2deg(bias.x()), gm::rad2deg(bias.y()), gm::rad2deg(bias.z()), b_ref_n.x(), b_ref_n.y(),
                     b_ref_n.z(), gm::rad2deg(std::sqrt(res_var.x())), gm::rad2deg(std::sqrt(res_var.y())),
                     gm::rad2deg(std::sqrt(res_var.z())));
    });
    return m.run();
} catch (const std::exception& e) {
    std::fprintf(stderr, "gdnav-example-attitude: %s\n", e.what());
    return 2;
}
