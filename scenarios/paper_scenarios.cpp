#include "paper_scenarios.hpp"

#include <cmath>
#include <optional>

#include "random/stream.hpp"
#include "framework/scenario_generator.hpp"
#include "scenario_yaml.hpp"

namespace gdnav::scenario {

using config::Config;
using config::ConfigError;
using config::Range;

namespace {

void apply_fixed(const Config& f, int scenario, guidance::Scenario2Draws& m) {
    auto& c = m.common;
    auto fix = [&](const char* key, double& field, Range r, bool angle) {
        if (f.has(key)) field = angle ? f.get_angle_deg(key, r) : f.get_double(key, r);
    };
    fix("bearing_ini_deg", c.bearing_ini_rad, {-180.0, 180.0}, true);
    fix("bearing_end_deg", c.bearing_end_rad, {-180.0, 180.0}, true);
    fix("airspeed_ini_mps", c.airspeed_ini_mps, {15.0, 45.0}, false);
    fix("airspeed_end_mps", c.airspeed_end_mps, {15.0, 45.0}, false);
    fix("airspeed_delay_s", c.airspeed_delay_s, {1e-3, 1e6}, false);
    fix("altitude_delay_s", c.altitude_delay_s, {1e-3, 1e6}, false);
    fix("Hp_ini_m", c.pressure_altitude_ini_m, {0.0, 8000.0}, false);
    fix("Hp_end_m", c.pressure_altitude_end_m, {0.0, 8000.0}, false);
    fix("turn_time_s", c.turn_time_s, {-1e4, 1e6}, false);
    if (scenario == 2) {
        if (f.has("legs_s")) {
            const auto v = f.get_doubles("legs_s", 7, 7, {1e-3, 1e6});
            for (std::size_t i = 0; i < 7; ++i) m.leg_s[i] = v[i];
        }
        if (f.has("bearings_deg")) {
            const auto v = f.get_doubles("bearings_deg", 7, 7, {-180.0, 180.0});
            for (std::size_t i = 0; i < 7; ++i) m.bearing_rad[i] = math::deg2rad(v[i]);
        }
    }
    f.finish();
}

YAML::Node until_time(double t_s) {
    YAML::Node n = flow_map();
    n["trigger"] = "time";
    n["t_s"] = number(t_s);
    return n;
}


YAML::Node turn_op(double to_rad, const YAML::Node& until) {
    const guidance::ManoeuvreSettings m;
    YAML::Node op;
    op["op"] = "turn";
    op["to_bearing_deg"] = degrees(to_rad);
    op["bank_deg"] = degrees(m.turn_bank_rad);
    op["lead_deg"] = degrees(m.turn_lead_rad);
    op["until"] = until;
    return op;
}

// A drawn ramp as its section of the scenario file.
template <class P, std::size_t N>
YAML::Node ramp_yaml(const P& p, const std::array<config::NumberKey<P>, N>& keys) {
    YAML::Node n;
    for (const config::NumberKey<P>& k : keys) n[k.key] = k.degrees ? degrees(p.*k.field) : number(p.*k.field);
    return n;
}

YAML::Node earth_yaml(const earth::EarthTruthParams& e) {
    YAML::Node n;
    n["dg_mps2"] = number(e.dg_mps2);
    n["tilt_deg"] = degrees(e.tilt_rad);
    n["tilt_axis_bearing_deg"] = degrees(e.tilt_axis_bearing_rad);
    YAML::Node m(YAML::NodeType::Sequence);
    m.SetStyle(YAML::EmitterStyle::Flow);
    for (int i = 0; i < 3; ++i) m.push_back(number(e.mag_dev_n_nT[i]));
    n["mag_dev_n_nT"] = m;
    return n;
}

// Names of the components of `doc` whose type is `type`.
std::vector<std::string> members_of_type(const YAML::Node& comps, const std::string& type) {
    std::vector<std::string> v;
    if (!comps || !comps.IsMap()) return v;
    for (const auto& kv : comps)
        if (kv.second.IsMap() && kv.second["type"] && kv.second["type"].IsScalar() &&
            kv.second["type"].Scalar() == type)
            v.push_back(kv.first.as<std::string>());
    return v;
}

// Moves run.t0_s back by `dt_s` and lengthens the run by as much (duration_s, or steps when the file gives steps).
void start_earlier(YAML::Node& doc, double dt_s, const std::string& origin) {
    YAML::Node run = doc["run"];
    if (!run || !run.IsMap()) throw ConfigError("config error: " + origin + ": key 'run': missing (required)");
    const Config rc = Config::wrap(run, origin, "run");
    const double dt = rc.get_double("dt_s", 0.01, Range{1e-4, 1.0});
    run["t0_s"] = number(rc.get_double("t0_s", 0.0, Range{-1e6, 1e6}) - dt_s);
    if (run["steps"])
        run["steps"] = rc.get_int("steps", 1, 100'000'000) + static_cast<std::int64_t>(std::llround(dt_s / dt));
    else
        run["duration_s"] = number(rc.get_double("duration_s", Range{dt, 1e6}) + dt_s);
}

}  // namespace

PaperDraws draw_paper_scenario(int scenario, std::uint64_t seed, std::uint64_t run_index, const Config* options) {
    if (scenario != 1 && scenario != 2) throw std::invalid_argument("paper scenario must be 1 or 2");
    PaperDraws d;
    d.scenario = scenario;
    d.seed = seed;
    d.run_index = run_index;
    d.t_end_s = scenario == 1 ? 3800.0 : 500.0;
    if (options) {
        d.t_gnss_s = options->get_double("t_gnss_s", 100.0, Range{-1e6, 1e7});
        d.t_end_s = options->get_double("t_end_s", d.t_end_s, Range{1e-3, 1e6});
    }
    rnd::Stream ms = rnd::Stream::derive(seed, run_index, "scenario/mission");
    rnd::Stream ws = rnd::Stream::derive(seed, run_index, "scenario/wind");
    rnd::Stream os = rnd::Stream::derive(seed, run_index, "scenario/offsets");
    rnd::Stream es = rnd::Stream::derive(seed, run_index, "scenario/earth");
    if (scenario == 1)
        d.mission.common = guidance::draw_scenario1(ms, d.t_gnss_s);
    else
        d.mission = guidance::draw_scenario2(ms, d.t_gnss_s);
    d.wind = physics::draw_wind_scenario(ws, scenario == 1);
    d.offsets = atm::draw_offsets_scenario(os, scenario == 1);
    d.earth = earth::draw_earth_truth(es);
    if (options) {
        if (auto f = options->optional_child("fixed")) apply_fixed(*f, scenario, d.mission);
        if (auto c = options->optional_child("calibration")) d.calibration = parse_calibration(*c);
    }
    return d;
}

guidance::Mission paper_mission(const PaperDraws& d) {
    return d.scenario == 1 ? guidance::make_scenario1_mission(d.mission.common, d.t_end_s)
                           : guidance::make_scenario2_mission(d.mission, d.t_end_s);
}

YAML::Node paper_mission_yaml(const PaperDraws& d) {
    const auto& c = d.mission.common;
    const guidance::ManoeuvreSettings m;
    YAML::Node mission;
    mission["name"] = "paper_scenario" + std::to_string(d.scenario) + "_seed" + std::to_string(d.seed) + "_run" +
                      std::to_string(d.run_index);
    mission["t_end_s"] = number(d.t_end_s);
    YAML::Node ops = d.calibration ? calibration_operations(*d.calibration, c.airspeed_ini_mps,
                                                            c.pressure_altitude_ini_m, c.bearing_ini_rad)
                                   : YAML::Node(YAML::NodeType::Sequence);
    YAML::Node hold;
    hold["op"] = "hold";
    hold["throttle"] = channel("airspeed", "airspeed_mps", number(c.airspeed_ini_mps));
    hold["elevator"] = channel("pressure_altitude", "pressure_altitude_m", number(c.pressure_altitude_ini_m));
    hold["aileron"] = channel("bearing", "bearing_deg", degrees(c.bearing_ini_rad));
    hold["rudder"] = channel("sideslip", "sideslip_deg", number(0.0));
    hold["until"] = until_time(c.turn_time_s);
    ops.push_back(hold);
    if (d.scenario == 1) {
        ops.push_back(turn_op(c.bearing_end_rad, until_elapsed(c.airspeed_delay_s)));
        YAML::Node speed;
        speed["op"] = "airspeed_change";
        speed["to_airspeed_mps"] = number(c.airspeed_end_mps);
        speed["until"] = until_elapsed(c.altitude_delay_s);
        ops.push_back(speed);
        YAML::Node alt;
        alt["op"] = "altitude_change";
        alt["to_pressure_altitude_m"] = number(c.pressure_altitude_end_m);
        alt["path_angle_deg"] = degrees(m.climb_path_angle_rad);
        alt["until"] = until_time(d.t_end_s);
        ops.push_back(alt);
    } else {
        for (std::size_t k = 0; k < 8; ++k) {
            const double chi = k == 0 ? c.bearing_end_rad : d.mission.bearing_rad[k - 1];
            ops.push_back(turn_op(chi, k < 7 ? until_elapsed(d.mission.leg_s[k]) : until_time(d.t_end_s)));
        }
    }
    mission["operations"] = ops;
    return mission;
}

GeneratedScenario generate_paper_scenario(int scenario, const YAML::Node& doc_in, std::uint64_t seed,
                                          std::uint64_t run_index, const std::string& origin) {
    GeneratedScenario g;
    g.doc = YAML::Clone(doc_in);
    std::optional<Config> options;
    if (g.doc["generator"]) options.emplace(Config::wrap(g.doc["generator"], origin, "generator"));
    if (options) (void)options->get_string("name");
    g.draws = draw_paper_scenario(scenario, seed, run_index, options ? &*options : nullptr);
    if (options) options->finish();
    g.doc.remove("generator");
    const PaperDraws& d = g.draws;
    if (d.calibration) start_earlier(g.doc, calibration_duration_s(*d.calibration, d.mission.common.airspeed_ini_mps),
                                     origin);

    YAML::Node comps = g.doc["components"];
    if (!comps || !comps.IsMap()) throw ConfigError("config error: " + origin + ": key 'components': missing (required)");
    bool mission_given = false;
    for (const auto& name : members_of_type(comps, "guidance")) mission_given = mission_given || comps[name]["mission"];
    for (const auto& name : members_of_type(comps, "guidance")) {
        YAML::Node drawn;
        drawn["mission"] = paper_mission_yaml(d);
        fill_missing(comps[name], drawn, "components." + name, &g.kept);
    }
    for (const auto& name : members_of_type(comps, "flight_physics")) {
        YAML::Node drawn;
        const YAML::Node init = static_cast<const YAML::Node&>(comps[name])["initial"];
        if (!mission_given && !(init && init.IsMap() && init["mission"])) {
            YAML::Node i = flow_map();
            i["tas_mps"] = number(d.mission.common.airspeed_ini_mps);
            i["Hp_m"] = number(d.mission.common.pressure_altitude_ini_m);
            i["bearing_deg"] = degrees(d.mission.common.bearing_ini_rad);
            drawn["initial"] = i;
        }
        drawn["wind"] = ramp_yaml(d.wind, physics::kWindRampKeys);
        drawn["offsets"] = ramp_yaml(d.offsets, atm::kOffsetsRampKeys);
        drawn["earth_truth"] = earth_yaml(d.earth);
        fill_missing(comps[name], drawn, "components." + name, &g.kept);
    }
    for (const auto& name : members_of_type(comps, "sensors_gnss")) {
        const YAML::Node c = comps[name];
        if (c["never_lost"]) continue;
        YAML::Node drawn;
        drawn["loss_time_s"] = number(d.t_gnss_s);
        fill_missing(comps[name], drawn, "components." + name, &g.kept);
    }
    for (const auto& name : members_of_type(comps, "nav_recorder")) {
        YAML::Node drawn;
        drawn["t_gnss_s"] = number(d.t_gnss_s);
        fill_missing(comps[name], drawn, "components." + name, &g.kept);
    }
    return g;
}

void register_paper_scenarios() {
    for (int s : {1, 2}) {
        framework::register_scenario_generator(
            "paper_scenario" + std::to_string(s),
            [s](const YAML::Node& doc, std::uint64_t seed, std::uint64_t run, const std::string& origin) {
                return generate_paper_scenario(s, doc, seed, run, origin).doc;
            });
    }
}

}  // namespace gdnav::scenario
