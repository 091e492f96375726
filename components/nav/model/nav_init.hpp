#pragma once
// Initial estimates of the attitude and position filters (docs/navigation.md "Initialisation, `init.mode`").
//
// Two modes, chosen by `init.mode` in each filter's tuning section:
//  * alignment (the paper's runs): the filters start from the pre-flight fine alignment the sensors publish with
//      their samples (ImuSample / MagSample align_*; emulated with the reference's error model,
//      docs/sensors.md "Pre-flight fine alignment"): q_nb, E_gyr, E_acc, E_mag, B_dev and their 1-sigma. The attitude
//      P0 is the reference's fixed 1e-8 per quaternion component (`init.alignment.q_p0`); 0 uses the published
//      attitude sigma instead. No truth is read.
//  * measurements (no alignment available): everything comes from the first measurements and the first GNSS fix.
//      attitude: leveling from the specific force corrected for the turn term, g_b = -(f~ - w~ x v_tas_b), and
//                magnetic heading from the levelled magnetometer and the model declination:
//                  pitch = atan2(-g_x, sqrt(g_y^2 + g_z^2)), bank = atan2(g_y, g_z),
//                  B_h = R_y(pitch) R_x(bank) B~,  yaw = atan2(B_model_E, B_model_N) - atan2(B_h,y, B_h,x);
//                E_gyr, E_mag, B_dev, E_acc start at 0 with the 1-sigma of the sensor-grade bias offsets /
//                WMM error budget given in the tuning file.
#include "nav_types.hpp"

namespace gdnav::nav {

enum class InitMode { kMeasurements, kAlignment };

// Truth-free mode 1-sigmas.
struct MeasurementInitSigmas {
    double tilt_rad{0.026};     // about N and E: one-sample levelling (accelerometer bias / g and turbulence)
    double heading_rad{0.087};  // about D: magnetic heading (hard iron, field model error, tilt through the dip)
    Vec3 gyr_bias_rps{Vec3::Constant(3.49e-3)};
    Vec3 acc_bias_mps2{Vec3::Constant(0.157)};
    Vec3 mag_bias_nT{Vec3::Constant(530.0)};
    Vec3 b_dev_nT{138.0, 89.0, 165.0};
};

// Coarse attitude from one specific-force sample (gravity direction g_b, already corrected for the turn term)
// and one magnetometer sample (bias-corrected), with the model field b_model_n giving the declination.
Quat coarse_attitude(const Vec3& f_corrected_b, const Vec3& b_b_nT, const Vec3& b_model_n_nT);

}  // namespace gdnav::nav
