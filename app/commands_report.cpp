// gdnav report DIR [DIR2 ...]: the paper's aggregated tables and figures of one or more batch directories
// (launch/batch/batch_report.hpp). gdnav compare BASE CANDIDATE...: the paired comparison of batches that flew the
// same missions, which tools/report/compare.py implements (the command passes its arguments on).
#include <memory>

#include "commands.hpp"
#include "launch/batch/batch_report.hpp"

namespace gdnav::cli {

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
        launch::batch::ReportOptions o;
        o.figures = !a->no_figures;
        o.review = !a->no_review;
        o.out = a->out;
        std::vector<fs::path> dirs(a->dirs.begin(), a->dirs.end());
        return launch::batch::write_batch_report(dirs, o);
    };
    return sub;
}

CLI::App* add_compare_command(CLI::App& app, CliContext& ctx, CommandRunner& run) {
    struct Args {
        std::vector<std::string> dirs;
        std::string labels;
        std::string out;
        bool no_run_pages{false};
    };
    auto a = std::make_shared<Args>();
    auto* sub = app.add_subcommand(
        "compare", "paired comparison of batches of the same missions: tables, paired differences, Wilcoxon p, HTML");
    sub->add_option("dirs", a->dirs, "BASE CANDIDATE [CANDIDATE...]: batch directories (gdnav montecarlo --out)")
        ->required();
    sub->add_option("--labels", a->labels, "comma-separated labels, one per batch (default: the folder names)");
    sub->add_option("--out", a->out, "folder of the HTML page compare.html and its figures (default: no page)");
    sub->add_flag("--no-run-pages", a->no_run_pages,
                  "link runs without a review page (BATCH/report/review/) to their folder instead of writing the page");
    run = [a, &ctx]() {
        setup_logging("gdnav", ctx.log_level);
        std::vector<std::string> args(a->dirs.begin(), a->dirs.end());
        if (!a->labels.empty()) args.insert(args.end(), {"--labels", a->labels});
        if (!a->out.empty()) args.insert(args.end(), {"--out", a->out});
        if (a->no_run_pages) args.emplace_back("--no-run-pages");
        // compare.py prints its own one-line errors (exit 2 for bad input or batches of different missions).
        return launch::batch::run_report_tool("compare.py", args, false);
    };
    return sub;
}

}  // namespace gdnav::cli
