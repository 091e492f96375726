#pragma once
// Every gdnav subcommand. To add one: write add_<name>_command in its own file and list it in cli.cpp's table.
#include "command.hpp"

namespace gdnav::cli {

CLI::App* add_run_command(CLI::App& app, CliContext& ctx, CommandRunner& run);
CLI::App* add_component_command(CLI::App& app, CliContext& ctx, CommandRunner& run);
CLI::App* add_clock_command(CLI::App& app, CliContext& ctx, CommandRunner& run);
CLI::App* add_validate_command(CLI::App& app, CliContext& ctx, CommandRunner& run);
CLI::App* add_list_command(CLI::App& app, CliContext& ctx, CommandRunner& run);
CLI::App* add_bench_command(CLI::App& app, CliContext& ctx, CommandRunner& run);
CLI::App* add_scenario_command(CLI::App& app, CliContext& ctx, CommandRunner& run);
CLI::App* add_montecarlo_command(CLI::App& app, CliContext& ctx, CommandRunner& run);
CLI::App* add_report_command(CLI::App& app, CliContext& ctx, CommandRunner& run);
CLI::App* add_compare_command(CLI::App& app, CliContext& ctx, CommandRunner& run);
CLI::App* add_import_log_command(CLI::App& app, CliContext& ctx, CommandRunner& run);
CLI::App* add_export_log_command(CLI::App& app, CliContext& ctx, CommandRunner& run);
CLI::App* add_fault_command(CLI::App& app, CliContext& ctx, CommandRunner& run);
CLI::App* add_pki_command(CLI::App& app, CliContext& ctx, CommandRunner& run);
CLI::App* add_host_command(CLI::App& app, CliContext& ctx, CommandRunner& run);

// What `gdnav validate --scenario S` does, callable in-process (tests/integration/config_fuzz_test.cpp): loads the
// scenario (name in config/scenarios or YAML file), constructs and configures every component (each reads and checks
// its files) and orders the step graph. Throws config::ConfigError, one line naming file and key, for anything
// invalid; returns the summary line ("<file>: valid; N components, ...").
std::string validate_scenario(const std::string& scenario, const framework::ComponentRegistry& reg);

}  // namespace gdnav::cli
