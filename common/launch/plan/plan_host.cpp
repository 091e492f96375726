#include "launch/plan/plan_host.hpp"

#include <unistd.h>

#include <algorithm>
#include <cstdlib>
#include <fstream>

#include <yaml-cpp/yaml.h>

#include "config/config.hpp"

namespace gdnav::launch::deploy {

namespace fs = std::filesystem;

namespace {

// The run: the scenario with the plan's run keys, domain and profile (same on every host).
framework::RunConfig plan_run_config(const Plan& plan, const PlanHostRequest& req, const fs::path& scenario_file,
                          const fs::path& out, const fs::path& xml, const framework::ComponentRegistry& reg) {
    YAML::Node doc = YAML::LoadFile(scenario_file.string());
    if (plan.run_overrides)
        for (const auto& kv : plan.run_overrides) doc["run"][kv.first.as<std::string>()] = YAML::Clone(kv.second);
    doc["run"]["dds_profile"] = xml.string();
    framework::RunOverrides o;
    o.domain_id = plan.domain_id;
    o.out_dir = out.string();
    if (plan.seed) o.seed = *plan.seed;
    if (req.steps > 0) o.steps = req.steps;
    YAML::Emitter em;
    em.SetDoublePrecision(17);
    em << doc;
    framework::RunConfig rc = framework::RunConfig::parse(em.c_str(), scenario_file.string(), o);
    if (!req.rw.empty()) rc = launch::apply_run_rewrites(rc, req.rw, reg);
    return rc;
}

// The launcher's options for the host: its members of the run, the clock if it has it, its discovery server(s).
LaunchOptions host_launch_options(const Plan& plan, const PlanHost& host, const std::vector<std::string>& names,
                                  const std::string& log_level) {
    LaunchOptions lo;
    lo.layout = host.process;
    lo.log_level = log_level;
    lo.slice = true;
    lo.start_clock = host.clock;
    for (const auto& m : host.members)
        if (std::find(names.begin(), names.end(), m) != names.end()) lo.only.push_back(m);
    int id = 0;
    for (const std::string* s : {&plan.server_host, &plan.backup_host}) {
        if (!s->empty() && *s == host.name)
            lo.services.push_back({"discovery server " + std::to_string(id),
                                   {find_program(kDiscoveryServerProgram).string(), "-i", std::to_string(id), "-l",
                                    host.address, "-p", std::to_string(plan.server_port + id)}});
        ++id;
    }
    return lo;
}

std::string host_summary(const Plan& plan, const PlanHost& host, const LaunchOptions& lo) {
    std::string elsewhere;
    for (const auto& h : plan.hosts)
        if (h.name != host.name) {
            std::string ms;
            for (const auto& m : h.members) ms += (ms.empty() ? "" : ",") + m;
            elsewhere += (elsewhere.empty() ? "" : "; ") + h.name + " (" + h.address + "): " +
                         (h.clock ? std::string("clock") + (ms.empty() ? "" : ",") : std::string()) + ms;
        }
    std::string mine;
    for (const auto& m : lo.only) mine += (mine.empty() ? "" : ",") + m;
    return "plan " + plan.file.string() + ": host " + host.name + " (" + host.address + ") runs " +
           (host.clock ? "the clock, " : "") + mine + " as " + host.process + ", discovery " + plan.discovery +
           ", DDS domain " + std::to_string(plan.domain_id) + "; other hosts: " +
           (elsewhere.empty() ? "none" : elsewhere);
}

}  // namespace

fs::path find_program(const std::string& program) {
    const char* path = std::getenv("PATH");
    const std::string dirs = path ? path : "";
    for (std::size_t p = 0; p <= dirs.size();) {
        const auto c = dirs.find(':', p);
        const std::string d = dirs.substr(p, c == std::string::npos ? std::string::npos : c - p);
        const fs::path f = fs::path(d.empty() ? "." : d) / program;
        if (access(f.c_str(), X_OK) == 0 && !fs::is_directory(f)) return fs::absolute(f);
        if (c == std::string::npos) break;
        p = c + 1;
    }
    throw config::ConfigError("config error: " + program +
                              " not found on PATH (the plan's discovery server; Debian: apt-get install fastdds-tools)");
}

PlanHostRun plan_host_run(const Plan& plan, const PlanHostRequest& req, const fs::path& scenario_file,
                          const framework::ComponentRegistry& reg) {
    const PlanHost& host = req.host.empty() ? plan.clock_host() : plan.host(req.host);
    const fs::path out = req.out.empty() ? fs::path("out/plan") / host.name : req.out;
    fs::create_directories(out);
    const fs::path xml = fs::absolute(out / "dds_plan.xml");
    std::ofstream(xml) << plan_profile_xml(plan);
    PlanHostRun r{plan_run_config(plan, req, scenario_file, out, xml, reg), {}, {}};
    std::vector<std::string> names;
    for (const auto& m : r.rc.members) names.push_back(m.name);
    plan.check_members(names, r.rc.external);
    r.lo = host_launch_options(plan, host, names, req.log_level);
    r.summary = host_summary(plan, host, r.lo);
    return r;
}

}  // namespace gdnav::launch::deploy
