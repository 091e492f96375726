#include "sensors/model/grades.hpp"

#include "math/rotation.hpp"

namespace gdnav::sensors {

using config::Config;
using config::Range;

namespace {
// Upper bounds are sanity limits (orders of magnitude above any grade in the paper), not physics.
constexpr double kBig = 1.0e6;
const Range kSigma{0.0, kBig};
const Range kRatio{0.0, 0.5};  // scale factor / cross coupling sigmas

// A whole grade file (or mapping): the optional `description`, the grade's own keys (`read`), then no other key.
template <class Grade, class Read>
Grade grade_file(const Config& cfg, Read read) {
    (void)cfg.get_string("description", "");
    Grade g;
    read(g);
    cfg.finish();
    return g;
}

// The scale-factor and cross-coupling sigmas, ratios named alike in the triad and magnetometer grades.
template <class Grade>
void read_ratios(const Config& cfg, Grade& g) {
    g.scale_factor = cfg.get_double("scale_factor", kRatio);
    g.cross_coupling = cfg.get_double("cross_coupling", kRatio);
}

// The keys of a triad grade that carry the sensor's unit (the file's units differ between gyroscopes and
// accelerometers); scale_factor and cross_coupling are ratios (read_ratios).
struct TriadKeys {
    const char* bias_drift;
    const char* system_noise;
    const char* bias_offset;
};

// A whole triad grade file; `unit` converts the file's unit to SI (exact for 1.0).
TriadGrade triad(const Config& cfg, const TriadKeys& keys, double unit) {
    return grade_file<TriadGrade>(cfg, [&](TriadGrade& g) {
        g.bias_drift = cfg.get_double(keys.bias_drift, kSigma) * unit;
        g.system_noise = cfg.get_double(keys.system_noise, kSigma) * unit;
        read_ratios(cfg, g);
        g.bias_offset = cfg.get_double(keys.bias_offset, kSigma) * unit;
    });
}

ScalarGrade scalar(const Config& cfg, const char* noise_key, const char* offset_key, double unit) {
    ScalarGrade g;
    g.noise = cfg.get_double(noise_key, kSigma) * unit;
    g.bias_offset = cfg.get_double(offset_key, kSigma) * unit;
    return g;
}
}  // namespace

TriadGrade parse_gyro_grade(const Config& cfg) {
    return triad(cfg, {"bias_drift_deg_s1p5", "system_noise_deg_s0p5", "bias_offset_deg_s"}, math::kDeg);
}

TriadGrade parse_acc_grade(const Config& cfg) {
    return triad(cfg, {"bias_drift_m_s2p5", "system_noise_m_s1p5", "bias_offset_m_s2"}, 1.0);
}

MagGrade parse_mag_grade(const Config& cfg) {
    return grade_file<MagGrade>(cfg, [&](MagGrade& g) {
        g.system_noise_nT_rts = cfg.get_double("system_noise_nT_s0p5", kSigma);
        read_ratios(cfg, g);
        g.hard_iron_nT = cfg.get_double("hard_iron_nT", kSigma);
        g.bias_offset_nT = cfg.get_double("bias_offset_nT", kSigma);
    });
}

AirGrade parse_air_grade(const Config& cfg) {
    return grade_file<AirGrade>(cfg, [&](AirGrade& g) {
        g.tas_mps = scalar(cfg, "tas_noise_m_s", "tas_bias_offset_m_s", 1.0);
        g.aoa_rad = scalar(cfg, "aoa_noise_deg", "aoa_bias_offset_deg", math::kDeg);
        g.aos_rad = scalar(cfg, "aos_noise_deg", "aos_bias_offset_deg", math::kDeg);
    });
}

AtmGrade parse_atm_grade(const Config& cfg) {
    return grade_file<AtmGrade>(cfg, [&](AtmGrade& g) {
        g.p_Pa = scalar(cfg, "pressure_noise_Pa", "pressure_bias_offset_Pa", 1.0);
        g.T_K = scalar(cfg, "temperature_noise_K", "temperature_bias_offset_K", 1.0);
    });
}

GnssGrade parse_gnss_grade(const Config& cfg) {
    return grade_file<GnssGrade>(cfg, [&](GnssGrade& g) {
        g.horizontal_m = cfg.get_double("horizontal_noise_m", kSigma);
        g.vertical_m = cfg.get_double("vertical_noise_m", kSigma);
        g.velocity_mps = cfg.get_double("velocity_noise_m_s", kSigma);
        g.iono_step_m = cfg.get_double("iono_step_m", kSigma);
        g.iono_initial_steps = cfg.get_double("iono_initial_steps", kSigma);
        // The soft band needs room for its 20-step pull zone on each side.
        g.iono_band_steps = cfg.get_double("iono_band_steps", Range{40.0, kBig});
        g.iono_update_fixes = static_cast<int>(cfg.get_int("iono_update_fixes", 1, 100000));
        g.fix_period_s = cfg.get_double("fix_period_s", Range{0.01, 3600.0});
    });
}

}  // namespace gdnav::sensors
