// Ranges of the `calibration` keys (file units):
//   pattern      turns | s_turns (required)
//   bank_deg     [5, 30]    bank of the pattern's turns (30: the mission format's bank limit)
//   lead_in_s    [1, 600]   straight flight on chi_0 before the pattern (default 20)
//   settle_s     [0, 600]   straight flight after the pattern before the file's t0 (default 30)
//   cycles       [1, 10]    s_turns only (default 2)
//   amplitude_deg [10, 180] s_turns only (default 90)
#include "calibration_pattern.hpp"

#include <cmath>
#include <cstdio>

#include "earth/wgs84.hpp"
#include "math/rotation.hpp"
#include "scenario_yaml.hpp"

namespace gdnav::scenario {

using config::Range;

namespace {

YAML::Node bank_op(double bank_rad, double dt_s) {
    YAML::Node op;
    op["op"] = "hold";
    op["aileron"] = channel("bank", "bank_deg", number(math::rad2deg(bank_rad)));
    op["until"] = until_elapsed(dt_s);
    return op;
}

double turn_rate_rps(const CalibrationPattern& p, double airspeed_mps) {
    return earth::kG0_mps2 * std::tan(p.bank_rad) / airspeed_mps;
}

double pattern_s(const CalibrationPattern& p, double airspeed_mps) {
    const double w = turn_rate_rps(p, airspeed_mps);
    if (p.kind == CalibrationPattern::Kind::turns) return 2.0 * (2.0 * math::kPi / w);
    return p.cycles * 4.0 * p.amplitude_rad / w;
}

}  // namespace

CalibrationPattern parse_calibration(const config::Config& c) {
    CalibrationPattern p;
    p.kind = c.get_choice("pattern", {"turns", "s_turns"}) == "turns" ? CalibrationPattern::Kind::turns
                                                                      : CalibrationPattern::Kind::s_turns;
    p.bank_rad = c.get_angle_deg("bank_deg", Range{5.0, 30.0});
    p.lead_in_s = c.get_double("lead_in_s", 20.0, Range{1.0, 600.0});
    p.settle_s = c.get_double("settle_s", 30.0, Range{0.0, 600.0});
    if (p.kind == CalibrationPattern::Kind::s_turns) {
        p.cycles = static_cast<int>(c.get_int("cycles", 2, 1, 10));
        p.amplitude_rad = math::deg2rad(c.get_double("amplitude_deg", 90.0, Range{10.0, 180.0}));
    }
    c.finish();
    return p;
}

double calibration_duration_s(const CalibrationPattern& p, double airspeed_mps) {
    return std::ceil(p.lead_in_s + pattern_s(p, airspeed_mps) + p.settle_s);
}

YAML::Node calibration_operations(const CalibrationPattern& p, double airspeed_mps, double pressure_altitude_m,
                                  double bearing_rad) {
    YAML::Node ops(YAML::NodeType::Sequence);
    YAML::Node lead;
    lead["op"] = "hold";
    lead["throttle"] = channel("airspeed", "airspeed_mps", number(airspeed_mps));
    lead["elevator"] = channel("pressure_altitude", "pressure_altitude_m", number(pressure_altitude_m));
    lead["aileron"] = channel("bearing", "bearing_deg", degrees(bearing_rad));
    lead["rudder"] = channel("sideslip", "sideslip_deg", number(0.0));
    lead["until"] = until_elapsed(p.lead_in_s);
    ops.push_back(lead);
    const double w = turn_rate_rps(p, airspeed_mps);
    if (p.kind == CalibrationPattern::Kind::turns) {
        ops.push_back(bank_op(p.bank_rad, 2.0 * math::kPi / w));
        ops.push_back(bank_op(-p.bank_rad, 2.0 * math::kPi / w));
    } else {
        const double t = p.amplitude_rad / w;
        for (int k = 0; k < p.cycles; ++k) {
            ops.push_back(bank_op(p.bank_rad, t));
            ops.push_back(bank_op(-p.bank_rad, 2.0 * t));
            ops.push_back(bank_op(p.bank_rad, t));
        }
    }
    return ops;
}

std::string describe_calibration(const CalibrationPattern& p, double airspeed_mps) {
    char b[256];
    if (p.kind == CalibrationPattern::Kind::turns)
        std::snprintf(b, sizeof(b),
                      "calibration: 360 deg turn right then left at bank %.0f deg (%.1f s each), %.0f s before t0\n",
                      math::rad2deg(p.bank_rad), 2.0 * math::kPi / turn_rate_rps(p, airspeed_mps),
                      calibration_duration_s(p, airspeed_mps));
    else
        std::snprintf(b, sizeof(b), "calibration: %d S-turn cycles of +-%.0f deg at bank %.0f deg, %.0f s before t0\n",
                      p.cycles, math::rad2deg(p.amplitude_rad), math::rad2deg(p.bank_rad),
                      calibration_duration_s(p, airspeed_mps));
    return b;
}

}  // namespace gdnav::scenario
