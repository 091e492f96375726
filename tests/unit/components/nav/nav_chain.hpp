#pragma once
// Runs the three navigation filters in the step order of the architecture (air -> attitude(p_n of k-1) -> position)
// on synthetic data, with the repository's tuning and variant files (optionally edited).
#include <functional>
#include <string>
#include <vector>

#include <yaml-cpp/yaml.h>

#include "air_data_filter.hpp"
#include "attitude_filter.hpp"
#include "config/config.hpp"
#include "math/rotation.hpp"
#include "nav_earth.hpp"
#include "nav_synthetic.hpp"
#include "nav_test_util.hpp"
#include "position_filter.hpp"

namespace gdnav::nav::test {

struct ChainOptions {
    std::string variant{"baseline"};
    bool reference_init{true};   // init.mode alignment (truth + the reference's small errors) instead of measurements
    int steps{6000};
    int last_fix_step{-1};       // fixes after this step are dropped (-1: never)
    int dead_at_step{-1};        // call set_gnss_publisher_dead() before this step (-1: never)
    YAML::Node attitude_override;  // merged into tuning.attitude (e.g. r, q_per_step)
    YAML::Node position_override;  // merged into tuning.position (e.g. gnss_integrity)
    std::function<void(int, synth::Sample&)> edit;  // optional: alters the sample of step k before the filters see it
    std::function<void(int, const PositionFilter&)> inspect;  // optional: called after the position step of step k
    std::function<void(int, PositionFilter&)> before_position;  // optional: called before the position step of step k
};

struct ChainRun {
    std::vector<synth::Sample> data;
    std::vector<AirDataEstimate> air;
    std::vector<AttitudeEstimate> att;
    std::vector<PositionEstimate> pos;
};

inline void merge(YAML::Node dst, const YAML::Node& src) {
    for (const auto& kv : src) {
        const std::string k = kv.first.as<std::string>();
        if (kv.second.IsMap() && dst[k].IsMap()) {
            merge(dst[k], kv.second);
        } else {
            dst[k] = kv.second;
        }
    }
}

inline YAML::Node load_tuning_node(bool reference_init) {
    YAML::Node t = YAML::LoadFile(source_path("config/nav/tuning.yaml"));
    const char* mode = reference_init ? "alignment" : "measurements";
    t["attitude"]["init"]["mode"] = mode;
    t["position"]["init"]["mode"] = mode;
    return t;
}

inline ChainRun run_chain(const synth::Scenario& sc, const ChainOptions& o, std::uint64_t seed) {
    YAML::Node tn = load_tuning_node(o.reference_init);
    if (o.attitude_override) merge(tn["attitude"], o.attitude_override);
    if (o.position_override) merge(tn["position"], o.position_override);
    const config::Config tuning = config::Config::wrap(tn, "tuning.yaml");
    const config::Config variant = config::Config::load(source_path("config/nav/variants/" + o.variant + ".yaml"));
    const rnd::Stream root = rnd::Stream::derive(seed, 0, "nav_test");
    AirDataFilter air;
    AttitudeFilter att;
    PositionFilter pos;
    air.configure(tuning.child("air"), root.child("air"));
    att.configure(tuning.child("attitude"), variant.child("attitude"), root.child("att"));
    pos.configure(tuning.child("position"), variant.child("position"), root.child("pos"));
    synth::Generator gen(sc, root.child("data"));
    const Alignment align = gen.alignment(root.child("alignment"));
    ChainRun run;
    run.data.reserve(static_cast<std::size_t>(o.steps) + 1);
    for (int k = 0; k <= o.steps; ++k) {
        synth::Sample s = gen.next();
        if (o.last_fix_step >= 0 && k > o.last_fix_step) s.gnss.fix_valid = false;
        if (o.edit) o.edit(k, s);
        const double t = s.truth.t_s;
        if (k == 0) {
            run.air.push_back(air.initialize(0, t, s.air, s.atm));
            run.att.push_back(att.initialize(0, t, s.imu, s.mag, run.air.back(), s.gnss, &align));
            run.pos.push_back(pos.initialize(0, t, s.imu, s.gnss, run.air.back(), run.att.back(), &align));
        } else {
            if (k == o.dead_at_step) pos.set_gnss_publisher_dead();
            const auto uk = static_cast<std::uint64_t>(k);
            run.air.push_back(air.step(uk, t, s.air, s.atm));
            run.att.push_back(att.step(uk, t, s.imu, s.mag, run.pos.back()));
            if (o.before_position) o.before_position(k, pos);
            run.pos.push_back(pos.step(uk, t, s.imu, s.gnss, run.air.back(), run.att.back()));
        }
        if (o.inspect) o.inspect(k, pos);
        run.data.push_back(s);
    }
    return run;
}

// Attitude error angle [rad] between estimate and truth.
inline double att_error(const ChainRun& r, std::size_t k) {
    return math::angle_between(r.att[k].q_nb, r.data[k].truth.q_nb);
}

// Horizontal position error [m].
inline double hor_error_m(const ChainRun& r, std::size_t k) {
    const auto& p = r.pos[k];
    const auto& t = r.data[k].truth;
    const earth::Radii rr = earth::radii(t.lat_rad);
    const double dn = (p.lat_rad - t.lat_rad) * (rr.m_m + t.h_m);
    const double de = math::wrap_pi(p.lon_rad - t.lon_rad) * (rr.n_m + t.h_m) * std::cos(t.lat_rad);
    return std::hypot(dn, de);
}

}  // namespace gdnav::nav::test
