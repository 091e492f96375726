#pragma once
// Low-frequency wind: horizontal, uniform in space, "wind ramp" in time (reference section 3.1).
// v_wind^n(t) = (v_N(t), v_E(t), 0); the N and E components (not speed and bearing) are constant before t_ini,
// linear between t_ini and t_end, constant after t_end. Bearings are the direction the air moves TOWARDS:
// v_N = V cos(chi), v_E = V sin(chi).
//
// Stochastic definition, draws in this order (N ~ N(0, 1)), ramp times as in random/ramp_times.hpp:
//   1. t_ini       2. t_end with min_gap = s_t / 2
//   3. V_ini = |s_V0 N|       4. chi_ini ~ U{-179..180} integer degrees
//   5. V_end = V_ini + s_Vjump N       6. chi_end = chi_ini + s_chijump N;
//      if V_end < 0: V_end = -V_end, chi_end += 180 deg; chi_end wrapped to (-180, 180] deg.
// Scenario #1 ("wind_id03"): 400 s, 1200 s, 600 s, 50 s, s_V0 7 m/s, s_Vjump 3 m/s, s_chijump 15 deg.
// Scenario #2 ("wind_id04"): same draws with zero jumps (constant wind; same V_ini, chi_ini for one stream).
#include "config/number_keys.hpp"
#include "math/rotation.hpp"
#include "random/ramp_times.hpp"

namespace gdnav::physics {

struct WindRampParams {
    double t_ini_s{0.0};
    double t_end_s{0.0};
    double speed_ini_mps{0.0};
    double bearing_ini_rad{0.0};  // towards
    double speed_end_mps{0.0};
    double bearing_end_rad{0.0};
};

// The keys of a scenario's `wind:` section: flight_physics reads them, the paper scenarios write a drawn ramp.
inline constexpr std::array<config::NumberKey<WindRampParams>, 6> kWindRampKeys{{
    {"t_ini_s", &WindRampParams::t_ini_s, false, {-1e6, 1e7}},
    {"t_end_s", &WindRampParams::t_end_s, false, {-1e6, 1e7}, &WindRampParams::t_ini_s},
    {"speed_ini_mps", &WindRampParams::speed_ini_mps, false, {0.0, 60.0}},
    {"bearing_ini_deg", &WindRampParams::bearing_ini_rad, true, {-360.0, 360.0}},
    {"speed_end_mps", &WindRampParams::speed_end_mps, false, {0.0, 60.0}},
    {"bearing_end_deg", &WindRampParams::bearing_end_rad, true, {-360.0, 360.0}},
}};

struct WindRampSpec {
    rnd::RampTimesSpec times;
    double sigma_speed0_mps{7.0};
    double sigma_speed_jump_mps{3.0};
    double sigma_bearing_jump_rad{math::deg2rad(15.0)};
};

WindRampParams draw_wind_ramp(rnd::Stream& stream, const WindRampSpec& spec);
// The paper's scenarios: #1 (jumps) the default spec, #2 (no jumps) the same draws with zero jump sigmas.
WindRampParams draw_wind_scenario(rnd::Stream& stream, bool jumps);

class WindRamp {
public:
    WindRamp() = default;
    explicit WindRamp(const WindRampParams& p);
    [[nodiscard]] math::Vec3 wind_n_mps(double t_s) const;
    [[nodiscard]] const WindRampParams& params() const { return p_; }

private:
    WindRampParams p_{};
    math::Vec3 w_ini_{math::Vec3::Zero()};
    math::Vec3 w_end_{math::Vec3::Zero()};
};

}  // namespace gdnav::physics
