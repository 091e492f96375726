// gdnav report DIR [DIR2 ...]: the paper's aggregated tables and figures of one or more batch directories
// (launch/batch/batch_report.hpp).
#include <memory>

#include "commands.hpp"
#include "launch/batch/batch_report.hpp"

namespace gdnav::app {

namespace fs = std::filesystem;

CLI::App* add_report_command(CLI::App& app, CliContext& ctx, CommandRunner& run) {
    struct Args {
        std::vector<std::string> dirs;
        std::string out;
        bool no_figures{false};
        bool no_review{false};
    };
    auto a = std::make_shared<Args>();
    auto* sub = app.add_subcommand("report", "aggregate a Monte Carlo batch: the paper's tables and figures");
    sub->add_option("dirs", a->dirs, "batch directories (gdnav montecarlo --out); shards of one batch: merged; batches: side by side")->required();
    sub->add_option("--out", a->out, "output folder (default: <first dir>/report)");
    sub->add_flag("--no-figures", a->no_figures, "tables only");
    sub->add_flag("--no-review", a->no_review, "no HTML flight review pages (review.html, review/run_*.html)");
    run = [a, &ctx]() {
        setup_logging("gdnav", ctx.log_level);
        ReportOptions o;
        o.figures = !a->no_figures;
        o.review = !a->no_review;
        o.out = a->out;
        std::vector<fs::path> dirs(a->dirs.begin(), a->dirs.end());
        return write_batch_report(dirs, o);
    };
    return sub;
}

}  // namespace gdnav::app
