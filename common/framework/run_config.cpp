#include "framework/run_config.hpp"

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <fstream>
#include <map>
#include <set>
#include <sstream>

#include "framework/lockstep.hpp"
#include "framework/run_members.hpp"
#include "framework/scenario_generator.hpp"

#ifndef GDNAV_SOURCE_CONFIG_DIR
#define GDNAV_SOURCE_CONFIG_DIR "config"
#endif

namespace gdnav::framework {

using config::Config;
using config::ConfigError;
using config::Range;

std::filesystem::path config_dir() {
    if (const char* env = std::getenv("GDNAV_CONFIG_DIR"); env && *env) return env;
#ifdef GDNAV_INSTALL_CONFIG_DIR
    // An installed package used away from the source tree (cmake --install): its share/gdnav/config.
    std::error_code ec;
    if (!std::filesystem::is_directory(GDNAV_SOURCE_CONFIG_DIR, ec) && std::filesystem::is_directory(GDNAV_INSTALL_CONFIG_DIR, ec))
        return GDNAV_INSTALL_CONFIG_DIR;
#endif
    return GDNAV_SOURCE_CONFIG_DIR;
}

std::filesystem::path resolve_scenario(const std::string& s) {
    const std::filesystem::path p(s);
    const bool looks_like_file = s.find('/') != std::string::npos || p.extension() == ".yaml";
    if (looks_like_file) {
        if (!std::filesystem::is_regular_file(p)) throw ConfigError("config error: " + s + ": cannot open file");
        return p;
    }
    const auto dir = config_dir() / "scenarios";
    const auto named = dir / (s + ".yaml");
    if (std::filesystem::exists(named)) return named;
    std::string known;
    std::error_code ec;
    for (const auto& e : std::filesystem::directory_iterator(dir, ec))
        if (e.path().extension() == ".yaml") known += (known.empty() ? "" : ", ") + e.path().stem().string();
    throw ConfigError("config error: scenario '" + s + "' not found in " + dir.string() + " (available: " + known + ")");
}

RunConfig RunConfig::load(const std::filesystem::path& file, const RunOverrides& o) {
    std::ifstream in(file);
    if (!in) throw ConfigError("config error: " + file.string() + ": cannot open file");
    std::stringstream ss;
    ss << in.rdbuf();
    return parse(ss.str(), file.string(), o);
}

namespace {

// The command line's overrides, applied to the document before it is validated.
YAML::Node apply_overrides(const std::string& text, const std::string& origin, const RunOverrides& o) {
    Config probe = Config::parse(text, origin);
    YAML::Node root = YAML::Clone(probe.node());
    if (!root["run"] || !root["run"].IsMap())
        throw ConfigError("config error: " + origin + ": key 'run': missing (required)");
    if (o.seed) root["run"]["seed"] = *o.seed;
    if (o.run_index) root["run"]["run_index"] = *o.run_index;
    if (o.out_dir) root["run"]["out_dir"] = *o.out_dir;
    if (o.realtime) root["run"]["realtime"] = *o.realtime;
    if (o.domain_id) root["run"]["domain_id"] = *o.domain_id;
    if (o.external) {
        root["run"]["external"] = YAML::Node(YAML::NodeType::Sequence);
        for (const auto& n : *o.external) root["run"]["external"].push_back(n);
    }
    if (o.join_timeout_s) root["run"]["join_timeout_s"] = *o.join_timeout_s;
    if (o.security) root["run"]["security"] = o.security->string();
    // Made absolute here so the run.yaml that the launcher writes for its children names the same directory.
    if (root["run"]["security"] && root["run"]["security"].IsScalar())
        root["run"]["security"] =
            std::filesystem::absolute(root["run"]["security"].as<std::string>()).lexically_normal().string();
    if (o.faults_file) {
        // A run's <out>/faults.yaml (or any file with a `faults:` list): the schedule to apply instead.
        const Config f = Config::load(*o.faults_file);
        if (!f.has("faults")) f.fail("faults", "missing (required: the list of faults)");
        root["faults"] = YAML::Clone(f.node()["faults"]);
    }
    if (o.steps) {
        root["run"].remove("duration_s");
        root["run"]["steps"] = *o.steps;
    }
    return root;
}

// A `generator:` section: the named scenario generator draws the run's document for its seed and run index.
YAML::Node expand_generator(YAML::Node root, const std::string& origin) {
    if (!root["generator"]) return root;
    const Config top0 = Config::wrap(root, origin);
    const Config gen = top0.child("generator");
    const std::string name = gen.get_string("name");
    const ScenarioGenerator* g = find_scenario_generator(name);
    if (!g) {
        std::string known;
        for (const auto& n : scenario_generator_names()) known += (known.empty() ? "" : ", ") + n;
        gen.fail("name", "unknown scenario generator '" + name + "' (known: " + known + ")");
    }
    const Config run0 = top0.child("run");
    const std::uint64_t seed = run0.get_uint64("seed");
    const std::uint64_t index = run0.has("run_index") ? run0.get_uint64("run_index") : 0;
    root = (*g)(root, seed, index, origin);
    root.remove("generator");
    return root;
}

// The `run:` section: timing, timeouts, transport, members left outside, security, output.
void read_run_section(RunConfig& rc, const Config& run) {
    rc.info.seed = run.get_uint64("seed");
    rc.info.run_index = run.has("run_index") ? run.get_uint64("run_index") : 0;
    rc.info.dt_s = run.get_double("dt_s", 0.01, Range{1e-4, 1.0});
    rc.info.t0_s = run.get_double("t0_s", 0.0, Range{-1e6, 1e6});
    if (run.has("steps") && run.has("duration_s")) run.fail("steps", "give either steps or duration_s, not both");
    if (run.has("steps")) {
        rc.info.steps = static_cast<std::uint64_t>(run.get_int("steps", 1, 100'000'000));
    } else {
        const double d = run.get_double("duration_s", Range{rc.info.dt_s, 1e6});
        rc.info.steps = static_cast<std::uint64_t>(std::llround(d / rc.info.dt_s)) + 1;
    }
    rc.realtime = run.get_double("realtime", 0.0, Range{0.0, 1e6});
    rc.member_timeout_s = run.get_double("member_timeout_s", 1.5, Range{0.2, kMemberTimeoutMax_s});
    rc.startup_timeout_s = run.get_double("startup_timeout_s", 30.0, Range{1.0, 3600.0});
    rc.stall_timeout_s = run.get_double("stall_timeout_s", 60.0, Range{1.0, 86400.0});
    rc.window_steps = static_cast<std::uint64_t>(run.get_int("window_steps", 64, 0, 64));
    if (rc.realtime > 0.0) rc.window_steps = 0;
    rc.observer_nice = static_cast<int>(run.get_int("observer_nice", 19, 0, 19));
    rc.domain_given = run.has("domain_id");
    rc.domain_id = static_cast<int>(run.get_int("domain_id", 0, 0, 232));
    rc.essential = run.has("essential") ? run.get_strings("essential") : std::vector<std::string>{};
    rc.external = run.has("external") ? run.get_strings("external") : std::vector<std::string>{};
    rc.join_timeout_s = run.get_double("join_timeout_s", 60.0, Range{1.0, 86400.0});
    for (const auto& m : read_started_members(run)) {
        if (rc.is_external(m.name))
            run.fail("members." + m.name, "'" + m.name + "' is in run.external too (an external member is started "
                                          "by you, a member of run.members by gdnav: give it once)");
        if (!m.in_process()) rc.external.push_back(m.name);
    }
    rc.dds_profile = run.get_string("dds_profile", "dds/gdnav_profiles.xml");
    if (rc.dds_profile.is_relative()) rc.dds_profile = config_dir() / rc.dds_profile;
    if (run.has("security")) {
        rc.security_dir = run.get_string("security");
        if (!std::filesystem::is_directory(rc.security_dir))
            run.fail("security", "'" + rc.security_dir.string() +
                                     "' is not a directory (make one with `gdnav pki init DIR --scenario S`)");
    }
    rc.out_dir = run.get_string("out_dir", "out/run");
    rc.info.out_dir = rc.out_dir;
    run.finish();
}

// The `components:` section and the external members: names unique, at most 63, essential ones present.
void read_members(RunConfig& rc, const Config& top, const Config& run) {
    const Config comps = top.child("components");
    std::set<std::string> names;
    for (const auto& name : comps.keys()) {
        if (name == "clock") comps.fail(name, "'clock' is reserved for the lockstep clock");
        const Config c = comps.child(name);
        MemberSpec m{name, c.get_string("type"), c};
        names.insert(name);
        rc.members.push_back(std::move(m));
    }
    if (rc.members.empty()) comps.fail("", "at least one component is required");
    if (rc.members.size() > 63) comps.fail("", "at most 63 components per run");
    std::set<std::string> ext;
    for (const auto& e : rc.external) {
        if (e.empty() || e.size() > 63 || e.find_first_of(", \t") != std::string::npos)
            run.fail("external", "'" + e + "' is not a member name (1-63 characters, no commas or spaces)");
        if (e == kClockName) run.fail("external", "'clock' is the lockstep clock and cannot be external");
        if (!ext.insert(e).second) run.fail("external", "'" + e + "' is listed twice");
        names.insert(e);
    }
    if (names.size() > 63) run.fail("external", "at most 63 members per run (components and external members)");
    for (const auto& e : rc.essential)
        if (!names.count(e)) run.fail("essential", "'" + e + "' is not a member of this run");
}

// The fault schedule: parsed here, checked against the members' ports by build(). Errors name the faults file
// when one was given.
void read_faults(RunConfig& rc, const Config& top, const std::string& origin, const RunOverrides& o) {
    if (o.faults_file) {
        const Config f = Config::load(*o.faults_file);
        rc.faults = faults::FaultSchedule::parse(f, rc.info);
        f.finish();
        rc.faults_origin = o.faults_file->string();
    } else {
        rc.faults = faults::FaultSchedule::parse(top, rc.info);
        rc.faults_origin = origin;
    }
    if (rc.faults.to_yaml().size() > 8192)
        top.fail("faults", "the schedule takes more than 8192 characters of YAML (RunControl.faults); use fewer faults");
}

}  // namespace

RunConfig RunConfig::parse(const std::string& text, const std::string& origin, const RunOverrides& o) {
    // Parse once to apply overrides on the tree, then validate the resulting document.
    YAML::Node root = expand_generator(apply_overrides(text, origin, o), origin);
    apply_inprocess_members(root, origin);
    RunConfig rc;
    rc.origin = origin;
    rc.root_ = root;
    const Config top = Config::wrap(root, origin);
    const Config run = top.child("run");
    read_run_section(rc, run);
    read_members(rc, top, run);
    read_faults(rc, top, origin, o);
    // Only 'run', 'components' and 'faults' at top level; each component section is checked by build().
    for (const auto& k : top.keys())
        if (k != "run" && k != "components" && k != "faults")
            top.fail(k, "unknown key (allowed: run, components, faults)");
    return rc;
}

std::vector<std::unique_ptr<Component>> RunConfig::build(const ComponentRegistry& reg,
                                                         const std::vector<std::string>& only) const {
    std::vector<std::unique_ptr<Component>> out;
    for (const auto& m : members) {
        if (!only.empty() && std::find(only.begin(), only.end(), m.name) == only.end()) continue;
        out.push_back(build_one(reg, m.name));
    }
    for (const auto& n : only) {
        bool found = false;
        for (const auto& m : members) found = found || m.name == n;
        if (!found) throw ConfigError("config error: " + origin + ": no component named '" + n + "'");
    }
    if (only.empty() && !faults.empty()) {
        std::map<std::string, faults::MemberPorts> ports;
        for (const auto& c : out)
            for (const OutputBase* o : c->outputs()) ports[c->name()].outputs.push_back(o->topic());
        for (const auto& c : out) (void)ports[c->name()];
        for (const auto& e : external) ports[e].external = true;
        faults.validate(ports, faults_origin);
    }
    return out;
}

std::unique_ptr<Component> RunConfig::build_one(const ComponentRegistry& reg, const std::string& name) const {
    for (const auto& m : members) {
        if (m.name != name) continue;
        if (!reg.has(m.type)) {
            std::string known;
            for (const auto& t : reg.types()) known += (known.empty() ? "" : ", ") + t;
            m.cfg.fail("type", "unknown component type '" + m.type + "' (known: " + known + ")");
        }
        auto c = reg.create(m.type, m.name);
        rnd::Stream stream = rnd::Stream::derive(info.seed, info.run_index, m.name);
        c->configure(m.cfg, info, stream);
        m.cfg.finish();
        return c;
    }
    throw ConfigError("config error: " + origin + ": no component named '" + name + "'");
}

bool RunConfig::is_external(const std::string& name) const {
    return std::find(external.begin(), external.end(), name) != external.end();
}

std::vector<std::string> RunConfig::member_names() const {
    std::vector<std::string> v;
    for (const auto& m : members) v.push_back(m.name);
    for (const auto& e : external)
        if (std::find(v.begin(), v.end(), e) == v.end()) v.push_back(e);
    return v;
}

std::string RunConfig::to_yaml() const {
    YAML::Emitter em;
    em.SetDoublePrecision(17);
    em << root_;
    return std::string(em.c_str()) + "\n";
}

}  // namespace gdnav::framework
