// gdnav scenario: prints the values a scenario generator draws for (seed, run) and writes the resolved run config.
#include <cstdio>
#include <fstream>
#include <memory>

#include <spdlog/spdlog.h>

#include "commands.hpp"
#include "commands_scenario.hpp"
#include "paper_scenarios.hpp"
#include "framework/run_config.hpp"
#include "scenario_overrides.hpp"

namespace gdnav::cli {

namespace fs = std::filesystem;
using namespace gdnav::framework;

ScenarioDocument load_scenario_document(const std::string& name_or_file, const scenario::Overrides& o) {
    ScenarioDocument s;
    s.file = fs::absolute(resolve_scenario(scenario::scenario_alias(name_or_file)));
    const config::Config c = config::Config::load(s.file);  // clear error on malformed YAML
    s.doc = YAML::Clone(c.node());
    for (const auto& n : scenario::apply_overrides(s.doc, o, config_dir())) spdlog::warn("{}", n);
    return s;
}

std::string document_text(const YAML::Node& doc) {
    YAML::Emitter em;
    em.SetDoublePrecision(17);
    em << doc;
    return std::string(em.c_str()) + "\n";
}

CLI::App* add_scenario_command(CLI::App& app, CliContext& ctx, CommandRunner& run) {
    struct Args {
        std::string scenario{"1"};
        std::uint64_t seed{1};
        std::uint64_t run_index{0};
        std::string out;
        scenario::Overrides o;
        bool validate{false};
    };
    auto a = std::make_shared<Args>();
    auto* sub = app.add_subcommand("scenario", "print the values a scenario draws for (seed, run); write the run config");
    sub->add_option("--scenario", a->scenario, "1, 2 (paper scenarios), a scenario name or a YAML file");
    sub->add_option("--seed", a->seed, "master seed (default: the file's run.seed)");
    sub->add_option("--run", a->run_index, "run index inside the batch");
    sub->add_option("--out", a->out, "write the resolved run config (explicit values, no generator) to FILE");
    sub->add_option("--set", a->o.sets, "override a key: path.to.key=value (YAML value; ~ removes)");
    sub->add_option("--grade", a->o.grades, "sensor grade for every group (NAME) or one group (GROUP=NAME)");
    sub->add_option("--variant", a->o.variants, "navigation variant NAME (nav_att, nav_pos) or COMPONENT=NAME");
    sub->add_flag("--validate", a->validate, "also construct and configure every component");
    run = [a, sub, &ctx]() {
        setup_logging("gdnav", ctx.log_level);
        ScenarioDocument s = load_scenario_document(a->scenario, a->o);
        if (sub->count("--seed")) s.doc["run"]["seed"] = a->seed;
        s.doc["run"]["run_index"] = a->run_index;
        const std::string text = document_text(s.doc);
        const config::Config top = config::Config::wrap(s.doc, s.file.string());
        const std::string gen = s.doc["generator"] && s.doc["generator"]["name"] ? s.doc["generator"]["name"].Scalar() : "";
        const std::uint64_t seed = top.child("run").get_uint64("seed");
        if (gen == "paper_scenario1" || gen == "paper_scenario2") {
            const auto g = scenario::generate_paper_scenario(gen == "paper_scenario1" ? 1 : 2, s.doc, seed,
                                                             a->run_index, s.file.string());
            std::printf("%s: %s", s.file.c_str(), scenario::describe(g.draws).c_str());
            for (const auto& k : g.kept) std::printf("  note: %s is set by the scenario file (drawn value not used)\n", k.c_str());
        } else {
            std::printf("%s: %s\n", s.file.c_str(),
                        gen.empty() ? "no generator: every value is given in the file" : ("generator " + gen).c_str());
        }
        RunOverrides ro;
        ro.seed = seed;
        ro.run_index = a->run_index;
        const RunConfig rc = RunConfig::parse(text, s.file.string(), ro);
        if (a->validate) {
            (void)rc.build(ctx.registry);
            std::printf("valid: %zu components, %llu steps\n", rc.members.size(),
                        static_cast<unsigned long long>(rc.info.steps));
        }
        if (!a->out.empty()) {
            std::ofstream f(a->out);
            f << "# Resolved run config: " << s.file.string() << ", seed " << seed << ", run " << a->run_index
              << " (gdnav scenario)\n"
              << rc.to_yaml();
            if (!f) throw std::runtime_error("cannot write " + a->out);
            std::printf("resolved run config written to %s\n", a->out.c_str());
        }
        return 0;
    };
    return sub;
}

}  // namespace gdnav::cli
