// gdnav import-log / export-log: flight logs in the CSV layout of docs/replay.md <-> recorder files for replay.
#include <memory>

#include "commands.hpp"
#include "config/config.hpp"
#include "io/flight_log/log_export.hpp"
#include "io/flight_log/log_import.hpp"

namespace gdnav::cli {

CLI::App* add_import_log_command(CLI::App& app, CliContext& ctx, CommandRunner& run) {
    auto* sub = app.add_subcommand("import-log", "resample a CSV flight log onto the step grid as replayable records");
    auto o = std::make_shared<io::flight_log::ImportOptions>();
    auto steps = std::make_shared<std::uint64_t>(0);
    sub->add_option("csv_dir", o->csv_dir, "folder with imu.csv, mag.csv, air.csv, atm.csv, gnss.csv [alignment.csv]")
        ->required();
    sub->add_option("--out", o->run_dir, "run directory to write (RUN_DIR/record/*.cdr, for gdnav run --replay)")
        ->required();
    sub->add_option("--t0", o->t0_s, "simulated time of step 0 [s] (the scenario's run.t0_s)")->required();
    sub->add_option("--dt", o->dt_s, "step [s]")->capture_default_str();
    sub->add_option("--steps", *steps, "number of steps (default: as far as every continuous signal reaches)")
        ->check(CLI::PositiveNumber);
    sub->add_option("--max-gap", o->max_gap_s, "largest gap [s] allowed in imu/mag/air/atm")->capture_default_str();
    auto reference = std::make_shared<std::string>();
    sub->add_option("--reference", *reference,
                    "CSV of the true trajectory (t_s, position, velocity, attitude; docs/replay.md), replayed as Truth");
    run = [o, steps, reference, sub, &ctx]() {
        setup_logging("gdnav", ctx.log_level);
        if (sub->count("--steps")) o->steps = *steps;
        if (sub->count("--reference")) o->reference = *reference;
        io::flight_log::import_log(*o);
        return 0;
    };
    return sub;
}

CLI::App* add_export_log_command(CLI::App& app, CliContext& ctx, CommandRunner& run) {
    auto* sub = app.add_subcommand("export-log", "write a recorded run's sensor topics in the CSV flight-log layout");
    auto o = std::make_shared<io::flight_log::ExportOptions>();
    auto rates = std::make_shared<std::vector<std::string>>();
    sub->add_option("run_dir", o->run_dir, "a run directory with record/ (gdnav run --record ...)")->required();
    sub->add_option("--out", o->csv_dir, "folder to write the CSV files to")->required();
    sub->add_option("--rates", *rates, "GROUP=HZ[,GROUP=HZ...] (imu, mag, air, atm, gnss; default: every step)")
        ->delimiter(',');
    run = [o, rates, &ctx]() {
        setup_logging("gdnav", ctx.log_level);
        for (const auto& r : *rates) {
            const auto eq = r.find('=');
            double hz = 0.0;
            try {
                if (eq == std::string::npos) throw std::invalid_argument(r);
                std::size_t used = 0;
                hz = std::stod(r.substr(eq + 1), &used);
                if (used != r.size() - eq - 1) throw std::invalid_argument(r);
            } catch (const std::logic_error&) {
                throw config::ConfigError("config error: --rates: '" + r + "' is not GROUP=HZ (e.g. mag=50)");
            }
            o->rates_hz[r.substr(0, eq)] = hz;
        }
        io::flight_log::export_log(*o);
        return 0;
    };
    return sub;
}

}  // namespace gdnav::cli
