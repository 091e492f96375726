// gdnav compare end to end (tools/report/compare.py through the CLI): two 3-run direct batches of scenario #2 that
// fly the same missions, the baseline and the error-state attitude filter, 6000 steps (t = -50 .. 10 s: past t = 0,
// so the attitude metrics and finals exist, and before the GNSS loss at 100 s, so the final % is n/a).
//   * every run records its drawn scenario (drawn_scenario.yaml): the same in both batches, another per run;
//   * compare prints the paper's tables labelled by folder and the paired differences with Wilcoxon p-values, n/a
//     for the final %, and writes an HTML page whose paired scatters link to the runs' review pages;
//   * a batch of another seed is refused with one line and exit code 2;
//   * gdnav report A B labels its blocks by folder, the paper's "#2" kept.
#include <gtest/gtest.h>

#include <filesystem>
#include <regex>
#include <sstream>

#include "process_util.hpp"

using namespace gdnav::testing;
namespace fs = std::filesystem;

namespace {

fs::path batch(const std::string& tag, const std::string& seed, const std::string& runs,
               const std::vector<std::string>& more = {}) {
    const fs::path dir = temp_dir(tag);
    std::vector<std::string> cmd{kExe,      "montecarlo", "--scenario", "2",         "--runs",   runs,
                                 "--jobs",  "2",          "--layout",   "direct",    "--steps",  "6000",
                                 "--seed",  seed,         "--no-report", "--out",    dir.string()};
    cmd.insert(cmd.end(), more.begin(), more.end());
    const Result r = run(cmd, 120.0);
    EXPECT_EQ(r.exit_code, 0) << r.output;
    return dir;
}

fs::path run_folder(const fs::path& b, int i) { return b / "runs" / ("run_000" + std::to_string(i)); }

std::string line_with(const std::string& text, const std::string& start) {
    std::istringstream in(text);
    std::string line;
    while (std::getline(in, line))
        if (line.rfind(start, 0) == 0) return line;
    return "";
}

}  // namespace

TEST(Compare, PairsBatchesOfTheSameMissionsAndRefusesOthers) {
    const fs::path base = batch("cmp_base", "4", "3");
    const fs::path cand = batch("cmp_error_state", "4", "3", {"--variant", "att_error_state"});
    for (int i = 0; i < 3; ++i) {
        const std::string drawn = read_file(run_folder(base, i) / "drawn_scenario.yaml");
        EXPECT_NE(drawn.find("mission:"), std::string::npos) << drawn;
        EXPECT_EQ(drawn, read_file(run_folder(cand, i) / "drawn_scenario.yaml")) << i;
    }
    EXPECT_NE(read_file(run_folder(base, 0) / "drawn_scenario.yaml"),
              read_file(run_folder(base, 1) / "drawn_scenario.yaml"));

    const fs::path page = temp_dir("cmp_page");
    const Result r = run({kExe, "compare", base.string(), cand.string(), "--out", page.string()}, 240.0);
    ASSERT_EQ(r.exit_code, 0) << r.output;
    const std::string b = base.filename().string(), c = cand.filename().string();
    EXPECT_NE(r.output.find("| " + b + " | mean |"), std::string::npos) << r.output;  // the paper's tables
    EXPECT_NE(r.output.find("## " + c + " against " + b + ": paired over 3 runs (runs 0-2)"), std::string::npos);
    // A p-value in the attitude row (3 pairs: at least 0.25), n/a for the final % (the runs end before the loss).
    EXPECT_TRUE(std::regex_search(line_with(r.output, "| ‖Δr̂‖ run mean [deg]"),
                                  std::regex(R"(\| [0-3] of 3 \| (0\.\d+|1) \|$)")))
        << r.output;
    EXPECT_EQ(line_with(r.output, "| Δx_hor final [%]"), "| Δx_hor final [%] | n/a | n/a | n/a | n/a | n/a |")
        << r.output;
    EXPECT_EQ(r.output.find("could not be checked"), std::string::npos) << r.output;
    const std::string html = read_file(page / "compare.html");
    EXPECT_NE(html.find("<img src=\"paired_att_mean.png\" usemap=\"#map_att_mean\""), std::string::npos);
    EXPECT_NE(html.find("href=\"review/" + c + "/run_0000.html\""), std::string::npos);
    EXPECT_TRUE(fs::exists(page / "review" / c / "run_0000.html"));
    EXPECT_GT(fs::file_size(page / "bands.png"), 20000u);

    const fs::path other = batch("cmp_seed5", "5", "1");
    const Result o = run({kExe, "compare", base.string(), other.string()}, 60.0);
    EXPECT_EQ(o.exit_code, 2) << o.output;
    EXPECT_EQ(o.output, "compare: " + other.string() + " and " + base.string() +
                            " did not fly the same missions: different seeds (4 and 5, run 0)\n");

    const fs::path rep = temp_dir("cmp_report");
    const Result rr = run({kExe, "report", base.string(), cand.string(), "--no-figures", "--out", rep.string()}, 60.0);
    EXPECT_EQ(rr.exit_code, 0) << rr.output;
    const std::string tables = read_file(rep / "tables.md");
    EXPECT_NE(tables.find("| " + b + " (#2) | mean |"), std::string::npos) << tables;
    EXPECT_NE(tables.find("| " + c + " (#2) | mean |"), std::string::npos) << tables;
}
