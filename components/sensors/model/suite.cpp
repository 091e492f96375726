#include "sensors/model/suite.hpp"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <limits>

namespace gdnav::sensors {

using config::Config;
using config::ConfigError;
using config::Range;

namespace {

std::string available_grades(const std::filesystem::path& dir) {
    std::vector<std::string> names;
    std::error_code ec;
    for (const auto& e : std::filesystem::directory_iterator(dir, ec)) {
        if (e.path().extension() == ".yaml") names.push_back(e.path().stem().string());
    }
    std::sort(names.begin(), names.end());
    std::string s;
    for (const auto& n : names) s += (s.empty() ? "" : ", ") + n;
    return s.empty() ? "none" : s;
}

// One group's section of the suite: its `grade` names the grade file (the name is kept in `name`). The section is
// finished before the file is parsed, so a misspelt key in the suite is reported before any in the grade file.
template <class Parse>
auto group_grade(const Config& cfg, const char* group, const std::filesystem::path& grades_dir, std::string& name,
                 Parse parse) {
    const Config section = cfg.child(group);
    const Config file = load_grade(section, "grade", grades_dir, group, name);
    section.finish();
    return parse(file);
}

}  // namespace

Config load_grade(const Config& section, std::string_view key, const std::filesystem::path& grades_dir,
                  const std::string& group, std::string& name) {
    const std::string g = section.get_string(key);
    const bool ok = !g.empty() && std::all_of(g.begin(), g.end(), [](char c) {
        return std::isalnum(static_cast<unsigned char>(c)) || c == '_' || c == '-';
    });
    if (!ok) section.fail(key, "must be a grade name (letters, digits, '_', '-'), got '" + g + "'");
    const auto file = grades_dir / group / (g + ".yaml");
    if (!std::filesystem::exists(file))
        section.fail(key, "no grade '" + g + "' for " + group + ": no file " + file.string() +
                              " (available: " + available_grades(grades_dir / group) + ")");
    name = g;
    return load_grade_file(grades_dir, group, g);
}

Config load_grade_file(const std::filesystem::path& grades_dir, const std::string& group, const std::string& grade) {
    const auto file = grades_dir / group / (grade + ".yaml");
    if (!std::filesystem::exists(file)) {
        throw ConfigError("config error: " + file.string() + ": no grade '" + grade + "' for " + group +
                          " (available: " + available_grades(grades_dir / group) + ")");
    }
    return Config::load(file);
}

PlatformParams parse_platform(const Config& cfg) {
    PlatformParams p;
    p.imu_position_m = cfg.get_vec3("imu_position_m", Range{-10.0, 10.0});
    p.imu_position_error_m = cfg.get_double("imu_position_error_m", Range{0.0, 1.0});
    p.mounting_sigma_rad = cfg.get_vec3("mounting_sigma_deg", Range{0.0, 30.0}) * math::kDeg;
    p.mounting_estimate_error_rad = cfg.get_angle_deg("mounting_estimate_error_deg", Range{0.0, 30.0});
    p.cg_full_m = cfg.get_vec3("cg_full_m", Range{-10.0, 10.0});
    p.cg_empty_m = cfg.get_vec3("cg_empty_m", Range{-10.0, 10.0});
    p.mass_full_kg = cfg.get_double("mass_full_kg", Range{1.0e-3, 1.0e6});  // as the aircraft file
    p.mass_empty_kg = cfg.get_double("mass_empty_kg", Range{1.0e-3, p.mass_full_kg});
    cfg.finish();
    return p;
}

SensorSuiteParams parse_sensor_suite(const Config& cfg, const std::filesystem::path& grades_dir_in) {
    std::filesystem::path grades_dir = grades_dir_in;
    if (cfg.has("grades_dir")) grades_dir = grades_dir_in / cfg.get_string("grades_dir");

    SensorSuiteParams s;
    const double dt = cfg.get_double("sample_period_s", Range{1.0e-4, 1.0});
    const double t0 = cfg.get_double("start_time_s", Range{-1.0e7, 1.0e7});

    s.inertial.gyr = group_grade(cfg, "gyroscopes", grades_dir, s.gyr_grade, parse_gyro_grade);
    s.inertial.acc = group_grade(cfg, "accelerometers", grades_dir, s.acc_grade, parse_acc_grade);

    // Paper: 100 (baseline), 300 and 1000. The soft pull zone (20 steps) needs L >= 40.
    s.inertial.bias_drift_band = cfg.get_double("bias_drift_band", Range{40.0, 1.0e9});
    s.inertial.platform = parse_platform(cfg.child("platform"));
    s.inertial.dt_s = dt;
    s.alignment = AlignmentErrors::from_config(cfg.child("alignment"));

    s.mag.grade = group_grade(cfg, "magnetometers", grades_dir, s.mag_grade, parse_mag_grade);
    s.mag.dt_s = dt;

    s.air.grade = group_grade(cfg, "air_data", grades_dir, s.air_grade, parse_air_grade);
    s.atm.grade = group_grade(cfg, "atmospheric", grades_dir, s.atm_grade, parse_atm_grade);

    const Config gnss = cfg.child("gnss");
    const Config gnss_file = load_grade(gnss, "grade", grades_dir, "gnss", s.gnss_grade);
    if (gnss.has("loss_time_s")) s.gnss.loss_time_s = gnss.get_double("loss_time_s", Range{-1.0e7, 1.0e7});
    gnss.finish();
    s.gnss.grade = parse_gnss_grade(gnss_file);
    s.gnss.t0_s = t0;
    s.gnss.dt_s = dt;
    const double steps_per_fix = s.gnss.grade.fix_period_s / dt;
    if (std::abs(steps_per_fix - std::round(steps_per_fix)) > 1.0e-9 * steps_per_fix) {
        cfg.fail("sample_period_s", "the GNSS fix period must be a whole number of sensor steps");
    }
    cfg.finish();
    return s;
}

SensorSuiteParams load_sensor_suite(const std::filesystem::path& suite_file) {
    const Config cfg = Config::load(suite_file);
    return parse_sensor_suite(cfg, suite_file.parent_path());
}

std::vector<std::pair<std::string, double>> list_parameters(const SensorSuiteParams& s) {
    std::vector<std::pair<std::string, double>> out;
    auto triad = [&out](const std::string& p, const TriadGrade& g) {
        out.emplace_back(p + ".bias_drift", g.bias_drift);
        out.emplace_back(p + ".system_noise", g.system_noise);
        out.emplace_back(p + ".scale_factor", g.scale_factor);
        out.emplace_back(p + ".cross_coupling", g.cross_coupling);
        out.emplace_back(p + ".bias_offset", g.bias_offset);
    };
    auto scalar = [&out](const std::string& p, const ScalarGrade& g) {
        out.emplace_back(p + ".noise", g.noise);
        out.emplace_back(p + ".bias_offset", g.bias_offset);
    };
    auto vec = [&out](const std::string& p, const math::Vec3& v) {
        for (int i = 0; i < 3; ++i) out.emplace_back(p + "[" + std::to_string(i) + "]", v[i]);
    };
    triad("gyr", s.inertial.gyr);
    triad("acc", s.inertial.acc);
    out.emplace_back("inertial.bias_drift_band", s.inertial.bias_drift_band);
    out.emplace_back("inertial.dt_s", s.inertial.dt_s);
    const PlatformParams& p = s.inertial.platform;
    vec("platform.imu_position_m", p.imu_position_m);
    out.emplace_back("platform.imu_position_error_m", p.imu_position_error_m);
    vec("platform.mounting_sigma_rad", p.mounting_sigma_rad);
    out.emplace_back("platform.mounting_estimate_error_rad", p.mounting_estimate_error_rad);
    vec("platform.cg_full_m", p.cg_full_m);
    vec("platform.cg_empty_m", p.cg_empty_m);
    out.emplace_back("platform.mass_full_kg", p.mass_full_kg);
    out.emplace_back("platform.mass_empty_kg", p.mass_empty_kg);
    out.emplace_back("alignment.att_sigma_rad", s.alignment.att_sigma_rad);
    out.emplace_back("alignment.normalise_error_axis", s.alignment.normalise_error_axis ? 1.0 : 0.0);
    out.emplace_back("alignment.gyr_rel", s.alignment.gyr_rel);
    out.emplace_back("alignment.acc_rel", s.alignment.acc_rel);
    out.emplace_back("alignment.mag_rel", s.alignment.mag_rel);
    out.emplace_back("alignment.b_dev_rel", s.alignment.b_dev_rel);
    out.emplace_back("mag.system_noise_nT_rts", s.mag.grade.system_noise_nT_rts);
    out.emplace_back("mag.scale_factor", s.mag.grade.scale_factor);
    out.emplace_back("mag.cross_coupling", s.mag.grade.cross_coupling);
    out.emplace_back("mag.hard_iron_nT", s.mag.grade.hard_iron_nT);
    out.emplace_back("mag.bias_offset_nT", s.mag.grade.bias_offset_nT);
    out.emplace_back("mag.dt_s", s.mag.dt_s);
    scalar("air.tas_mps", s.air.grade.tas_mps);
    scalar("air.aoa_rad", s.air.grade.aoa_rad);
    scalar("air.aos_rad", s.air.grade.aos_rad);
    scalar("atm.p_Pa", s.atm.grade.p_Pa);
    scalar("atm.T_K", s.atm.grade.T_K);
    const GnssGrade& g = s.gnss.grade;
    out.emplace_back("gnss.horizontal_m", g.horizontal_m);
    out.emplace_back("gnss.vertical_m", g.vertical_m);
    out.emplace_back("gnss.velocity_mps", g.velocity_mps);
    out.emplace_back("gnss.iono_step_m", g.iono_step_m);
    out.emplace_back("gnss.iono_initial_steps", g.iono_initial_steps);
    out.emplace_back("gnss.iono_band_steps", g.iono_band_steps);
    out.emplace_back("gnss.iono_update_fixes", static_cast<double>(g.iono_update_fixes));
    out.emplace_back("gnss.fix_period_s", g.fix_period_s);
    out.emplace_back("gnss.t0_s", s.gnss.t0_s);
    out.emplace_back("gnss.dt_s", s.gnss.dt_s);
    out.emplace_back("gnss.loss_time_s", s.gnss.loss_time_s.value_or(std::numeric_limits<double>::infinity()));
    return out;
}

}  // namespace gdnav::sensors
