#include "launch/plan/plan.hpp"

#include <arpa/inet.h>

#include <algorithm>

#include <cstdio>
#include <fstream>
#include <set>
#include <sstream>

#include "config/config.hpp"
#include "framework/run_config.hpp"

namespace gdnav::launch::deploy {

namespace fs = std::filesystem;
using config::Config;
using config::ConfigError;

namespace {

bool is_ipv4(const std::string& a) {
    in_addr x{};
    return inet_pton(AF_INET, a.c_str(), &x) == 1;
}

std::string read_text(const fs::path& p) {
    std::ifstream f(p);
    std::stringstream ss;
    ss << f.rdbuf();
    return ss.str();
}

// Inserts `text` into the profile `xml` of `plan` right after `anchor`, or before it; a profile without the anchor is
// a configuration error naming the section the plan needs.
void insert_at(std::string& xml, const Plan& plan, const std::string& anchor, bool after, const std::string& text,
               const std::string& what) {
    const auto at = xml.find(anchor);
    if (at == std::string::npos)
        throw ConfigError("config error: " + plan.dds_profile.string() + ": no participant " + what);
    xml.insert(after ? at + anchor.size() : at, text);
}

}  // namespace

Plan Plan::load(const fs::path& file) {
    const Config top = Config::load(file);
    Plan p;
    p.file = file;
    p.scenario = top.get_string("scenario");
    if (top.has("seed")) p.seed = top.get_uint64("seed");
    p.domain_id = static_cast<int>(top.get_int("domain_id", 0, 232));
    p.discovery = top.get_choice("discovery", "peers", {"multicast", "peers", "server"});
    const std::string profile = top.get_string("dds_profile", "dds/gdnav_profiles.xml");
    p.dds_profile = fs::path(profile).is_relative() ? framework::config_dir() / profile : fs::path(profile);
    if (!fs::is_regular_file(p.dds_profile)) top.fail("dds_profile", "'" + p.dds_profile.string() + "': no such file");
    const Config hosts = top.child("hosts");
    std::set<std::string> seen_members, seen_addresses;
    int clocks = 0;
    for (const auto& name : hosts.keys()) {
        const Config h = hosts.child(name);
        PlanHost ph;
        ph.name = name;
        ph.address = h.get_string("address");
        if (!is_ipv4(ph.address)) h.fail("address", "'" + ph.address + "' is not an IPv4 address");
        if (!seen_addresses.insert(ph.address).second) h.fail("address", "'" + ph.address + "' is used by two hosts");
        ph.clock = h.get_bool("clock", false);
        clocks += ph.clock ? 1 : 0;
        ph.process = h.get_choice("process", "composed", {"composed", "distributed"});
        ph.members = h.has("members") ? h.get_strings("members") : std::vector<std::string>{};
        for (const auto& m : ph.members)
            if (!seen_members.insert(m).second) h.fail("members", "'" + m + "' is placed on two hosts");
        if (ph.members.empty() && !ph.clock) h.fail("members", "a host without the clock needs at least one member");
        h.finish();
        p.hosts.push_back(std::move(ph));
    }
    if (p.hosts.empty()) top.fail("hosts", "at least one host is required");
    if (clocks != 1) top.fail("hosts", "exactly one host must have 'clock: true' (found " + std::to_string(clocks) + ")");
    if (p.discovery == "server") {
        const Config s = top.child("server");
        p.server_host = s.get_string("host");
        p.backup_host = s.get_string("backup", "");
        p.server_port = static_cast<int>(s.get_int("port", 11811, 1024, 65535));
        for (const auto* k : {&p.server_host, &p.backup_host})
            if (!k->empty() && std::none_of(p.hosts.begin(), p.hosts.end(), [&](const PlanHost& h) { return h.name == *k; }))
                s.fail(k == &p.server_host ? "host" : "backup", "'" + *k + "' is not a host of this plan");
        if (p.backup_host == p.server_host) s.fail("backup", "the backup server must be on another host");
        s.finish();
    } else if (top.has("server")) {
        top.fail("server", "only with 'discovery: server'");
    }
    if (top.has("run")) {
        const Config r = top.child("run");
        p.run_overrides = YAML::Clone(r.node());
        for (const auto& k : r.keys()) {
            if (k == "domain_id" || k == "dds_profile" || k == "out_dir")
                r.fail(k, "set by the plan (domain_id, dds_profile) or by --out; remove it here");
            // Read here (marks it read); its value is checked with the run section by RunConfig::parse.
            if (r.node()[k].IsSequence())
                (void)r.get_strings(k);
            else if (r.node()[k].IsScalar())
                (void)r.get_string(k);
            else
                r.fail(k, "expected a value or a list (a key of the scenario's run section)");
        }
    }
    top.finish();
    return p;
}

const PlanHost& Plan::host(const std::string& name) const {
    for (const auto& h : hosts)
        if (h.name == name) return h;
    std::string known;
    for (const auto& h : hosts) known += (known.empty() ? "" : ", ") + h.name;
    throw ConfigError("config error: " + file.string() + ": key 'hosts': no host '" + name + "' (hosts: " + known + ")");
}

const PlanHost& Plan::clock_host() const {
    for (const auto& h : hosts)
        if (h.clock) return h;
    throw ConfigError("config error: " + file.string() + ": key 'hosts': no host has the clock");
}

void Plan::check_members(const std::vector<std::string>& run_members, const std::vector<std::string>& external) const {
    std::set<std::string> placed;
    for (const auto& h : hosts) placed.insert(h.members.begin(), h.members.end());
    const std::set<std::string> in_run(run_members.begin(), run_members.end());
    for (const auto& m : placed)
        if (!in_run.count(m) && m != "recorder")  // `recorder` exists only in runs with --record
            throw ConfigError("config error: " + file.string() + ": key 'hosts': member '" + m +
                              "' is not a component of scenario " + scenario);
    for (const auto& m : run_members) {
        const bool ext = std::find(external.begin(), external.end(), m) != external.end();
        if (!placed.count(m) && !ext)
            throw ConfigError("config error: " + file.string() + ": key 'hosts': member '" + m +
                              "' of scenario " + scenario + " is on no host (place it, or make it run.external)");
    }
}

std::string server_prefix(int id) {
    char buf[64];
    std::snprintf(buf, sizeof buf, "44.53.%02x.5f.45.50.52.4f.53.49.4d.41", id);
    return buf;
}

std::string plan_profile_xml(const Plan& plan) {
    std::string xml = read_text(plan.dds_profile);
    if (plan.discovery == "multicast") return xml;
    std::ostringstream add;
    if (plan.discovery == "peers") {
        add << "          <initialPeersList>\n";
        for (const auto& h : plan.hosts)
            add << "            <locator><udpv4><address>" << h.address << "</address></udpv4></locator>\n";
        add << "          </initialPeersList>\n";
        insert_at(xml, plan, "        </builtin>", false, add.str(),
                  "<builtin> section to add the plan's initial peers to");
        return xml;
    }
    add << "\n            <discoveryProtocol>CLIENT</discoveryProtocol>\n            <discoveryServersList>\n";
    int id = 0;
    for (const std::string* s : {&plan.server_host, &plan.backup_host}) {
        if (!s->empty())
            add << "              <RemoteServer prefix=\"" << server_prefix(id) << "\"><metatrafficUnicastLocatorList>"
                << "<locator><udpv4><address>" << plan.host(*s).address << "</address><port>" << plan.server_port + id
                << "</port></udpv4></locator></metatrafficUnicastLocatorList></RemoteServer>\n";
        ++id;
    }
    add << "            </discoveryServersList>";
    insert_at(xml, plan, "<discovery_config>", true, add.str(),
              "<discovery_config> section to add the plan's discovery servers to");
    return xml;
}

}  // namespace gdnav::launch::deploy
