// gdnav fault: injects a fault into a running run (launch/fault/fault_request.hpp, docs/faults.md "Live injection").
#include <memory>

#include <spdlog/spdlog.h>

#include "commands.hpp"
#include "dds/process/process_exit.hpp"
#include "launch/fault/fault_request.hpp"

namespace gdnav::cli {

namespace {

struct FaultArgs {
    launch::fault::FaultRequestSpec spec;
    double duration_s{0.0};
    std::uint64_t steps{0};
    double p{0.0};
};

}  // namespace

CLI::App* add_fault_command(CLI::App& app, CliContext& ctx, CommandRunner& run) {
    auto a = std::make_shared<FaultArgs>();
    auto* sub = app.add_subcommand("fault", "inject a fault into a running run (docs/faults.md)");
    sub->add_option("--domain", a->spec.domain, "DDS domain of the run")->required()->check(CLI::Range(0, 232));
    sub->add_option("--run", a->spec.run_index, "run index (default 0)");
    sub->add_option("--target", a->spec.target, "member whose samples (or which, for kill) the fault hits")->required();
    sub->add_option("--kind", a->spec.kind, "drop | freeze | bias | noise | delay | loss | nan | kill")
        ->required()
        ->check(CLI::IsMember({"drop", "freeze", "bias", "noise", "delay", "loss", "nan", "kill"}));
    sub->add_option("--topic", a->spec.topic, "one output topic of the target (default: all)");
    // At least one step: no run's step is shorter than run.dt_s's lower bound, 1e-4 s (framework/run_config.cpp);
    // the clock refuses a duration shorter than its own run's step.
    sub->add_option("--for", a->duration_s,
                    "duration in simulated seconds, at least one step of the run (run.dt_s, 0.01 s in the shipped "
                    "scenarios; default: to the end of the run)")
        ->check(CLI::Range(1e-4, 1e9));
    sub->add_option("--field", a->spec.fields, "bias/noise: NAME=VALUE (e.g. h_m=5, v_n_mps=[1,0,0]); nan: NAME");
    sub->add_option("--steps", a->steps, "delay: steps late")->check(CLI::Range(1, 1000));
    sub->add_option("--p", a->p, "loss: probability of dropping each sample")->check(CLI::Range(0.0, 1.0));
    sub->add_option("--security", a->spec.security, "DDS Security directory of a secure run (identity 'operator')");
    sub->add_option("--timeout", a->spec.timeout_s, "seconds to wait for the clock's answer")->check(CLI::Range(0.1, 3600.0));
    run = [a, sub, &ctx]() -> int {
        setup_logging("gdnav", ctx.log_level);
        launch::fault::FaultRequestSpec spec = a->spec;
        if (sub->count("--for")) spec.duration_s = a->duration_s;
        if (sub->count("--steps")) spec.steps = a->steps;
        if (sub->count("--p")) spec.p = a->p;
        const std::string entry = launch::fault::fault_entry_yaml(spec);
        // A DISPOSE into a running run can abort a member (dds/process/process_exit.hpp): leave without one.
        dds::keep_participants_until_exit();
        dds::exit_keeping_participants(launch::fault::send_fault_request(spec, entry));
    };
    return sub;
}

}  // namespace gdnav::cli
