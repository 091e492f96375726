#pragma once
// Time history of the INSA offsets dT (temperature) and dp (pressure) at mean sea level ("offsets ramp").
// Each offset is constant before its own t_ini, linear between t_ini and t_end, and constant after t_end; the two
// offsets have independent ramp times. No spatial dependence.
//
// Stochastic definition (reference section 2.1), draws in this order, N ~ N(0, 1), ramp times as in
// random/ramp_times.hpp with min_gap = s_t:
//   1. t_ini_T       2. t_ini_p: same, independently       3. t_end_T from t_ini_T       4. t_end_p from t_ini_p
//   5. dT_ini = s_dT0 N   6. dp_ini = s_dp0 N   7. dT_end = dT_ini + s_dTjump N   8. dp_end = dp_ini + s_dpjump N
// Scenario #1 ("offsets_id02"): t_ini_mean 400 s, dt_mean 1200 s, s_t 600 s, t_min 50 s, s_dT0 10 K,
//   s_dTjump 3 K, s_dp0 1500 Pa, s_dpjump 300 Pa. Scenario #2 ("offsets_id03"): same with zero jumps (constant
//   offsets; the ramp times and jump normals are still drawn so both scenarios share dT_ini, dp_ini for one stream).
#include "config/number_keys.hpp"
#include "random/ramp_times.hpp"

namespace gdnav::core::atm {

struct OffsetsRampParams {
    double dT_ini_K{0.0};
    double dT_end_K{0.0};
    double t_ini_dT_s{0.0};
    double t_end_dT_s{0.0};
    double dp_ini_Pa{0.0};
    double dp_end_Pa{0.0};
    double t_ini_dp_s{0.0};
    double t_end_dp_s{0.0};
};

// The keys of a scenario's `offsets:` section: flight_physics reads them, the paper scenarios write a drawn ramp.
inline constexpr std::array<config::NumberKey<OffsetsRampParams>, 8> kOffsetsRampKeys{{
    {"dT_ini_K", &OffsetsRampParams::dT_ini_K, false, {-60.0, 60.0}},
    {"dT_end_K", &OffsetsRampParams::dT_end_K, false, {-60.0, 60.0}},
    {"t_ini_dT_s", &OffsetsRampParams::t_ini_dT_s, false, {-1e6, 1e7}},
    {"t_end_dT_s", &OffsetsRampParams::t_end_dT_s, false, {-1e6, 1e7}, &OffsetsRampParams::t_ini_dT_s},
    {"dp_ini_Pa", &OffsetsRampParams::dp_ini_Pa, false, {-10000.0, 10000.0}},
    {"dp_end_Pa", &OffsetsRampParams::dp_end_Pa, false, {-10000.0, 10000.0}},
    {"t_ini_dp_s", &OffsetsRampParams::t_ini_dp_s, false, {-1e6, 1e7}},
    {"t_end_dp_s", &OffsetsRampParams::t_end_dp_s, false, {-1e6, 1e7}, &OffsetsRampParams::t_ini_dp_s},
}};

struct OffsetsRampSpec {
    rnd::RampTimesSpec times;
    double sigma_dT0_K{10.0};
    double sigma_dT_jump_K{3.0};
    double sigma_dp0_Pa{1500.0};
    double sigma_dp_jump_Pa{300.0};
};

OffsetsRampParams draw_offsets_ramp(rnd::Stream& stream, const OffsetsRampSpec& spec);
// The paper's scenarios: #1 (jumps) the default spec, #2 (no jumps) the same draws with zero jump sigmas.
OffsetsRampParams draw_offsets_scenario(rnd::Stream& stream, bool jumps);

struct Offsets {
    double dT_K{0.0};
    double dp_Pa{0.0};
};

class OffsetsRamp {
public:
    OffsetsRamp() = default;
    explicit OffsetsRamp(const OffsetsRampParams& p) : p_(p) {}
    [[nodiscard]] Offsets at(double t_s) const;
    [[nodiscard]] const OffsetsRampParams& params() const { return p_; }

private:
    OffsetsRampParams p_{};
};

// Piecewise-linear ramp: v0 before t0, v1 after t1, linear in between (t1 <= t0 means a step at t0).
double ramp_value(double t, double t0, double t1, double v0, double v1);

}  // namespace gdnav::core::atm
namespace gdnav { namespace atm = core::atm; }  // the short name (docs/architecture.md, "Namespaces")
