#pragma once
// Pre-flight fine alignment, emulated (docs/sensors.md, "Pre-flight fine alignment"). The reference starts its
// filters at t0 from a "fine-alignment-like" state: the true values plus small random errors, once per run. We
// model that alignment as a product of the sensor suite, so the navigation filters start from what the sensors
// publish and never read the truth: sensors_inertial publishes the attitude and the gyro/accelerometer full errors
// at t0, sensors_magnetic the magnetometer full error and the magnetic model deviation, each with its 1-sigma
// (ImuSample / MagSample `align_*`). A hardware-in-the-loop user replaces them with the outputs of a real alignment.
//
// Error model (baseline values of the reference; suite file `alignment:` section):
//   attitude  q = dq (x) q_true (error on the NED side), dq a rotation by gamma ~ N(0, 0.1 deg) about the axis
//             a = (cos p1 cos p2, sin p2, sin p1), p1 integer degrees U[-179, 180], p2 = (integer U[-179, 180]) / 2
//             degrees. The reference does not normalise `a` (|a| in [1, sqrt 2], inflating the angle); we
//             normalise it (`normalise_error_axis: false` restores the reference).
//   E_gyr, E_acc, E_mag = truth (x) (1 + 0.01 nu);  B_dev = truth (x) (1 + 0.1 nu);  nu ~ N(0, I3) per quantity.
//   1-sigma given with them: 0.01 |truth| (0.1 |truth| for B_dev) per axis; attitude: gamma's sigma.
// Draw order (one Stream per component, child "alignment"): IMU: attitude (gamma, p1, p2), E_gyr, E_acc;
// magnetometer: E_mag, B_dev.
#include "config/config.hpp"
#include "math/rotation.hpp"
#include "random/stream.hpp"

namespace gdnav::core::gnc {

struct AlignmentErrors {
    double att_sigma_rad{0.1 * 3.14159265358979323846 / 180.0};
    bool normalise_error_axis{true};
    double gyr_rel{0.01};
    double acc_rel{0.01};
    double mag_rel{0.01};
    double b_dev_rel{0.10};
    bool operator==(const AlignmentErrors&) const = default;
    // Keys att_error_sigma_deg [0, 10], normalise_error_axis, gyr_rel_error, acc_rel_error, mag_rel_error,
    // b_dev_rel_error [0, 1]; all required. Calls finish().
    static AlignmentErrors from_config(const config::Config& cfg);
};

struct ImuAlignment {
    math::Quat q_nb{math::Quat::Identity()};
    double att_sigma_rad{0.0};
    math::Vec3 gyr_err_rps{math::Vec3::Zero()}, gyr_err_sigma_rps{math::Vec3::Zero()};
    math::Vec3 acc_err_mps2{math::Vec3::Zero()}, acc_err_sigma_mps2{math::Vec3::Zero()};
};

struct MagAlignment {
    math::Vec3 mag_err_nT{math::Vec3::Zero()}, mag_err_sigma_nT{math::Vec3::Zero()};
    math::Vec3 b_dev_n_nT{math::Vec3::Zero()}, b_dev_sigma_nT{math::Vec3::Zero()};
};

// NED-side attitude error of the alignment (see above), drawn from `stream`.
math::Quat draw_attitude_error(double sigma_rad, bool normalise_axis, rnd::Stream& stream);
// truth (x) (1 + rel nu), nu ~ N(0, I3) (component-wise).
math::Vec3 perturb_relative(const math::Vec3& truth, double rel, rnd::Stream& stream);

// The alignment results from the true state at t0 (q_nb true, full sensor errors without noise, B_model - B_true).
ImuAlignment align_imu(const AlignmentErrors& e, const math::Quat& q_nb_true, const math::Vec3& gyr_err_rps,
                       const math::Vec3& acc_err_mps2, rnd::Stream& stream);
MagAlignment align_mag(const AlignmentErrors& e, const math::Vec3& mag_err_nT, const math::Vec3& b_dev_n_nT,
                       rnd::Stream& stream);

}  // namespace gdnav::core::gnc
namespace gdnav { namespace gnc = core::gnc; }  // the short name (docs/architecture.md, "Namespaces")

namespace gdnav::sensors {  // their names in the sensor models, where the alignment is emulated
using gnc::align_imu;
using gnc::align_mag;
using gnc::AlignmentErrors;
using gnc::draw_attitude_error;
using gnc::ImuAlignment;
using gnc::MagAlignment;
using gnc::perturb_relative;
}  // namespace gdnav::sensors
