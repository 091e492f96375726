// gdnav pki init: the DDS Security directory of a run (common/dds/security, docs/deployment.md "Security").
// Identities: the clock (Tick, RunControl, ComponentStatus), `operator` (FaultRequest, for gdnav fault), every
// configured member of the scenario (its output topics, StepDone, ComponentStatus), `composed` (every member's
// outputs: the process of the composed layout), `recorder` (added by gdnav run --record) and any --member NAME=TOPIC,... (an external member).
#include "commands.hpp"

#include <memory>
#include <set>

#include <spdlog/spdlog.h>

#include "commands_scenario.hpp"
#include "msgs/messages.hpp"
#include "framework/run_config.hpp"
#include "launch/pki/pki.hpp"
#include "dds/security/security.hpp"

namespace gdnav::app {

namespace {

namespace sec = runtime::security;

struct PkiArgs {
    std::string dir;
    std::string scenario{"default"};
    scenario::Overrides o;
    std::vector<std::string> members;  // NAME=TOPIC[,TOPIC...]
    int days{365};
};

std::vector<std::string> member_publish(std::vector<std::string> outputs) {
    outputs.push_back(topics::kStepDone);
    outputs.push_back(topics::kStatus);
    return outputs;
}

std::vector<sec::Identity> identities_for(const PkiArgs& a, const runtime::ComponentRegistry& reg) {
    const ScenarioDocument s = load_scenario_document(a.scenario, a.o);
    const runtime::RunConfig rc = runtime::RunConfig::parse(document_text(s.doc), s.file.string());
    std::vector<sec::Identity> ids{
        {sec::kClockIdentity, {topics::kTick, topics::kRunControl, topics::kStatus}},
        {sec::kOperatorIdentity, {topics::kFaultRequest}},
    };
    std::set<std::string> all_outputs;
    for (const auto& c : rc.build(reg)) {
        std::vector<std::string> outs;
        for (const auto* o : c->outputs()) {
            outs.push_back(o->topic());
            all_outputs.insert(o->topic());
        }
        ids.push_back({c->name(), member_publish(outs)});
    }
    std::set<std::string> names;
    for (const auto& id : ids) names.insert(id.name);
    // `gdnav run --record` adds a member `recorder` (no outputs) to any scenario.
    if (!names.count("recorder")) ids.push_back({"recorder", member_publish({})});
    ids.push_back({sec::kComposedIdentity, member_publish({all_outputs.begin(), all_outputs.end()})});
    names.insert("recorder");
    names.insert(sec::kComposedIdentity);
    for (const auto& m : a.members) {
        const auto eq = m.find('=');
        const std::string name = m.substr(0, eq);
        if (eq == std::string::npos || name.empty() || eq + 1 >= m.size())
            throw config::ConfigError("config error: --member '" + m +
                                      "': expected NAME=TOPIC[,TOPIC...] (the topics the member publishes)");
        if (!names.insert(name).second)
            throw config::ConfigError("config error: --member '" + name + "': identity already made for the scenario");
        std::vector<std::string> topics_of;
        std::string rest = m.substr(eq + 1);
        for (std::size_t p = 0; p <= rest.size();) {
            const auto c = rest.find(',', p);
            const std::string t = rest.substr(p, c == std::string::npos ? std::string::npos : c - p);
            if (!t.empty()) topics_of.push_back(t);
            if (c == std::string::npos) break;
            p = c + 1;
        }
        ids.push_back({name, member_publish(topics_of)});
    }
    return ids;
}

}  // namespace

CLI::App* add_pki_command(CLI::App& app, CliContext& ctx, CommandRunner& run) {
    auto a = std::make_shared<PkiArgs>();
    auto* pki = app.add_subcommand("pki", "DDS Security material for secure runs (docs/deployment.md)");
    pki->require_subcommand(1);
    auto* init = pki->add_subcommand("init", "make a CA, one certificate per identity, signed governance/permissions");
    init->add_option("dir", a->dir, "new directory to create (must not hold a CA yet)")->required();
    init->add_option("--scenario", a->scenario, "scenario whose members get identities (default: default)");
    init->add_option("--set", a->o.sets, "override a scenario key: path.to.key=value");
    init->add_option("--grade", a->o.grades, "sensor grade (as gdnav run)");
    init->add_option("--variant", a->o.variants, "navigation variant (as gdnav run)");
    init->add_option("--member", a->members,
                     "identity for an external member: NAME=TOPIC[,TOPIC...] (the data topics it may publish)");
    init->add_option("--days", a->days, "validity of certificates and grants in days")->check(CLI::Range(1, 36500));
    run = [a, &ctx]() {
        setup_logging("gdnav", ctx.log_level);
        const auto ids = identities_for(*a, ctx.registry);
        spdlog::info("gdnav pki: making a CA and {} identities in {} (openssl)", ids.size(), a->dir);
        sec::PkiOptions po;
        po.days = a->days;
        sec::init_pki(a->dir, ids, po);
        for (const auto& id : ids) sec::check_identity(a->dir, id.name);
        std::string names;
        for (const auto& id : ids) names += (names.empty() ? "" : ", ") + id.name;
        spdlog::info("gdnav pki: {} ready, valid {} days; identities: {}", a->dir, a->days, names);
        spdlog::info("use it with `gdnav run ... --security {}` (or run.security in the scenario)", a->dir);
        return 0;
    };
    return pki;
}

}  // namespace gdnav::app
