// gdnav pki init: the DDS Security directory of a run (common/dds/security, docs/deployment.md "Security"), with the
// identities of launch/pki/pki_identities.hpp.
#include "commands.hpp"

#include <memory>

#include <spdlog/spdlog.h>

#include "commands_scenario.hpp"
#include "framework/run_config.hpp"
#include "launch/pki/pki.hpp"
#include "launch/pki/pki_identities.hpp"
#include "dds/security/security.hpp"
#include "launch/pki/identity_check.hpp"

namespace gdnav::cli {

namespace {

namespace sec = launch::pki;

struct PkiArgs {
    std::string dir;
    std::string scenario{"default"};
    scenario::Overrides o;
    std::vector<std::string> members;  // NAME=TOPIC[,TOPIC...]
    int days{365};
};

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
        const ScenarioDocument s = load_scenario_document(a->scenario, a->o);
        const framework::RunConfig rc = framework::RunConfig::parse(document_text(s.doc), s.file.string());
        const auto ids = sec::run_identities(rc, ctx.registry, a->members);
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

}  // namespace gdnav::cli
