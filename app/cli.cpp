#include "cli.hpp"

#include <spdlog/sinks/stdout_color_sinks.h>
#include <spdlog/spdlog.h>

#include "commands.hpp"
#include "dds/process/run_cause.hpp"
#include "files/write_error.hpp"
#include "framework/lockstep.hpp"
#include "framework/topic_types.hpp"

namespace gdnav::cli {

void setup_logging(const std::string& who, const std::string& level) {
    auto logger = spdlog::stderr_color_mt(who);
    spdlog::set_default_logger(logger);
    spdlog::set_pattern("[%H:%M:%S.%e] [%n] %^%l%$: %v");
    spdlog::set_level(spdlog::level::from_str(level));
}

int cli_main(int argc, char** argv, const framework::ComponentRegistry& reg, const char* program_name) {
    framework::register_gdnav_topics();
    CLI::App app{"gdnav — GNSS-denied fixed-wing UAV simulation and navigation", program_name};
    app.require_subcommand(1);
    app.fallthrough();  // global options (--log-level) may follow the subcommand
    CliContext ctx{reg, "info", program_name};
    app.add_option("--log-level", ctx.log_level, "trace, debug, info, warn, error")
        ->check(CLI::IsMember({"trace", "debug", "info", "warn", "error", "off"}));

    static constexpr CommandFactory kCommands[] = {
        add_run_command, add_component_command, add_clock_command, add_validate_command,
        add_list_command, add_bench_command, add_scenario_command, add_montecarlo_command, add_report_command,
        add_compare_command,
        add_import_log_command, add_export_log_command, add_fault_command, add_pki_command,
        add_host_command,
    };
    std::vector<std::pair<CLI::App*, CommandRunner>> subs;
    for (CommandFactory f : kCommands) {
        CommandRunner r;
        CLI::App* s = f(app, ctx, r);
        subs.emplace_back(s, std::move(r));
    }
    try {
        app.parse(argc, argv);
    } catch (const CLI::ParseError& e) {
        if (e.get_exit_code() == 0) return app.exit(e);  // --help: the help text
        // A usage error is bad input like any other: one line and exit code 2 (CLI11's own codes, e.g. 105 for a
        // failed check or 109 for an extra argument, are not in gdnav's exit-code table).
        if (!spdlog::get("gdnav")) setup_logging("gdnav", "info");
        std::string where = program_name;
        for (const CLI::App* s : app.get_subcommands()) where += " " + s->get_name();
        spdlog::error("{} (usage: {} --help)", e.what(), where);
        return framework::kExitConfig;
    }
    try {
        for (auto& [s, r] : subs)
            if (s->parsed()) return r();
    } catch (const config::ConfigError& e) {
        if (!spdlog::get("gdnav")) setup_logging("gdnav", ctx.log_level);
        spdlog::error("{}", e.what());
        return framework::kExitConfig;
    } catch (const files::WriteError& e) {
        if (!spdlog::get("gdnav")) setup_logging("gdnav", ctx.log_level);
        spdlog::error("{}", e.what());
        dds::tell_launcher(e.what());  // a member process: its log may be on the same full disk
        return framework::kExitWriteFailed;
    } catch (const std::exception& e) {
        if (!spdlog::get("gdnav")) setup_logging("gdnav", ctx.log_level);
        spdlog::error("{}", e.what());
        return 1;
    }
    return 0;
}

}  // namespace gdnav::cli
