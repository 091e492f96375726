#pragma once
// Yaw from GNSS velocity with a Gaussian sum filter (in the spirit of PX4's EKF-GSF yaw estimator; docs/navigation.md,
// "In-flight alignment"): the heading that the turns make observable without the magnetometer.
//
// A bank of `models` 3-state EKFs x_i = [v_N, v_E, psi], started with headings spread evenly over the circle, the
// same velocity (the first GNSS fix) and P_psi = (pi / models)^2. Each step, with the tilt (pitch theta, bank phi) of
// the attitude filter and the IMU (gyro w_b less the estimated gyro bias, specific force f_b):
//   psi += dt (w_y sin phi + w_z cos phi) / cos theta                      (Euler kinematics)
//   b = levelled horizontal specific force, R_y(theta) R_x(phi) f_b rows x, y
//   v_NE += dt Rz(psi) b    (gravity has no horizontal part; Coriolis and transport terms are below the noise)
//   F = [[1, 0, -a_E dt], [0, 1, a_N dt], [0, 0, 1]],  Q = diag(s_a^2 dt^2, s_a^2 dt^2, s_w^2 dt^2)
// On a GNSS fix: z = v_NE, H = [I 0], R = s_v^2 I; weight_i *= N(r_i; 0, S_i), normalised (weights below 1e-6 of the
// largest are floored there so that no model dies for good).
// Heading: the weighted circular mean; variance sum_i w_i (P_psi,i + wrap(psi_i - mean)^2). With a constant heading
// every hypothesis explains the velocity equally (the specific force is vertical in the NED frame), so the weights
// stay spread and the variance large; a turn's centripetal acceleration rotates with psi and the wrong hypotheses
// predict the wrong velocity.
#include <array>
#include <vector>

#include "config/config.hpp"
#include "filters/ekf.hpp"
#include "math/rotation.hpp"

namespace gdnav::nav {

struct YawGsfSettings {
    int models{5};
    double accel_noise_mps2{1.0};      // s_a: levelled specific force error (tilt, turbulence)
    double rate_noise_rps{0.01};       // s_w
    double velocity_noise_mps{0.5};    // s_v: GNSS velocity and the unmodelled ground acceleration over a fix period
};

// Reads a `yaw_from_gnss` section's estimator keys (ranges in yaw_gsf.cpp).
YawGsfSettings parse_yaw_gsf(const config::Config& c);

class YawGsf {
public:
    YawGsf() = default;
    explicit YawGsf(const YawGsfSettings& s) : s_(s) {}

    // Starts the bank on the first fix's ground velocity.
    void start(const math::Vec3& v_n_mps);
    [[nodiscard]] bool started() const { return !models_.empty(); }
    void predict(double dt_s, const math::Vec3& w_b_rps, const math::Vec3& f_b_mps2, double pitch_rad, double bank_rad);
    void update(const math::Vec3& v_n_mps);

    [[nodiscard]] double yaw_rad() const;
    [[nodiscard]] double yaw_variance_rad2() const;
    // Mean magnitude of the levelled horizontal specific force over the predictions since the last update (0 before
    // any): the centripetal acceleration that makes the heading observable. In straight flight it is the size of
    // the turbulence, and the velocities say nothing of the heading, so a heading carried on from a turn is only
    // the gyro's integral (with the attitude filter's gyro bias) and must not be fused as if observed.
    [[nodiscard]] double turn_accel_mps2() const { return turn_accel_mps2_; }

private:
    struct Model {
        filters::Vec<3> x;
        filters::SqMat<3> p;
        double weight;
    };
    YawGsfSettings s_;
    std::vector<Model> models_;
    double accel_sum_mps2_{0.0};
    int accel_count_{0};
    double turn_accel_mps2_{0.0};
};

}  // namespace gdnav::nav
