// tools/report/results_tables.py (docs/results.md's tables regenerated from batch directories),
// checked against gdnav's own aggregation: two short 3-run scenario-#2 batches (the baseline and a paper variant),
// the script's figures equal those of `gdnav report` (report/aggregate.yaml), every table is well formed, --update
// replaces exactly the marked blocks, and a missing directory is one clear error.
#include <gtest/gtest.h>
#include <yaml-cpp/yaml.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <numbers>
#include <regex>
#include <sstream>

#include "process_util.hpp"

using namespace gdnav::testing;
namespace fs = std::filesystem;

namespace {

const std::string kScript = std::string(GDNAV_SOURCE_DIR) + "/tools/report/results_tables.py";

std::string fixed3(double v) {
    char b[32];
    std::snprintf(b, sizeof(b), "%.3f", v);
    return b;
}

// The cells of the table row that starts with `| first |` (empty when absent).
std::vector<std::string> row_cells(const std::string& md, const std::string& first) {
    std::istringstream in(md);
    std::string line;
    while (std::getline(in, line)) {
        if (line.rfind("| " + first + " |", 0) != 0) continue;
        std::vector<std::string> cells;
        std::string cell;
        std::istringstream l(line.substr(1));
        while (std::getline(l, cell, '|')) {
            cell.erase(0, cell.find_first_not_of(' '));
            cell.erase(cell.find_last_not_of(' ') + 1);
            cells.push_back(cell);
        }
        return cells;
    }
    return {};
}

class ResultsTables : public ::testing::Test {
protected:
    static void SetUpTestSuite() {
        root_ = temp_dir("results_tables");
        // 16000 steps from t0 = -50 s: past t_GNSS = 100 s, so final errors and percentages exist.
        for (const auto& [name, extra] : std::vector<std::pair<std::string, std::vector<std::string>>>{
                 {"s2_base", {}}, {"s2_var_att_zero_fb_derivatives", {"--variant", "att_zero_fb_derivatives"}}}) {
            std::vector<std::string> argv{kExe, "montecarlo", "--scenario", "2", "--runs", "3", "--jobs", "2",
                                          "--layout", "direct", "--seed", "1", "--steps", "16000", "--no-figures",
                                          "--out", (root_ / name).string()};
            argv.insert(argv.end(), extra.begin(), extra.end());
            const Result r = run(argv, 240.0);
            ASSERT_EQ(r.exit_code, 0) << r.output;
        }
        const Result t = run({"/usr/bin/python3", kScript, root_.string()}, 120.0);
        ASSERT_EQ(t.exit_code, 0) << t.output;
        tables_ = t.output;
    }
    static inline fs::path root_;
    static inline std::string tables_;
};

TEST_F(ResultsTables, SummaryEqualsGdnavReportAggregate) {
    for (const auto& [name, label] : std::vector<std::pair<std::string, std::string>>{
             {"s2_base", "base"}, {"s2_var_att_zero_fb_derivatives", "var_att_zero_fb_derivatives"}}) {
        const YAML::Node a = YAML::LoadFile((root_ / name / "report" / "aggregate.yaml").string());
        const double deg = 180.0 / std::numbers::pi;
        const auto cells = row_cells(tables_, label);
        ASSERT_GE(cells.size(), 12u) << label << "\n" << tables_;
        EXPECT_EQ(cells[1], "3");
        EXPECT_EQ(cells[2], fixed3(a["signals"]["rot_rad"]["mean"]["mean"].as<double>() * deg)) << label;
        EXPECT_EQ(cells[3], fixed3(a["signals"]["rot_rad"]["max"]["mean"].as<double>() * deg)) << label;
        char h[32];
        std::snprintf(h, sizeof(h), "%.2f", a["signals"]["h_m"]["final"]["std"].as<double>());
        EXPECT_EQ(cells[4], h) << label;
    }
    // The variant drops terms of the attitude filter's observation: its paired difference is a real figure.
    const auto v = row_cells(tables_, "var_att_zero_fb_derivatives");
    ASSERT_GE(v.size(), 12u);
    EXPECT_TRUE(std::regex_search(v[10], std::regex(R"(^[+−]\d+\.\d{4} ± \d+\.\d{4} \(\d\)$)"))) << v[10];
}

TEST_F(ResultsTables, EveryTableIsWellFormed) {
    for (const char* key : {"s2_summary", "s2_attitude_variants"})
        EXPECT_NE(tables_.find(std::string("<!-- table:") + key + " -->"), std::string::npos) << key;
    const int tables = expect_consistent_markdown_tables(tables_);
    EXPECT_EQ(tables_.find("n/a"), std::string::npos) << tables_;
    EXPECT_EQ(tables, 2);  // the summary and the attitude-variants group (the only group with two batches here)
}

TEST_F(ResultsTables, UpdateReplacesOnlyTheMarkedBlocks) {
    const fs::path md = root_ / "results.md";
    {
        std::ofstream f(md);
        f << "# Results\nprose before\n<!-- table:s2_summary -->\nold table\n<!-- /table -->\nprose between\n"
          << "<!-- table:s9_unknown -->\nkept\n<!-- /table -->\nprose after\n";
    }
    const Result r = run({"/usr/bin/python3", kScript, root_.string(), "--update", md.string()}, 120.0);
    ASSERT_EQ(r.exit_code, 0) << r.output;
    const std::string text = read_file(md);
    EXPECT_EQ(text.find("old table"), std::string::npos) << text;
    EXPECT_NE(text.find("| base | 3 |"), std::string::npos) << text;
    EXPECT_NE(text.find("<!-- table:s9_unknown -->\nkept\n<!-- /table -->"), std::string::npos) << text;
    EXPECT_NE(text.find("prose before"), std::string::npos);
    EXPECT_NE(text.find("prose between"), std::string::npos);
    EXPECT_NE(text.find("prose after"), std::string::npos);
    EXPECT_NE(r.output.find("no table 's9_unknown'"), std::string::npos) << r.output;
}

TEST_F(ResultsTables, MissingDirectoryIsOneClearError) {
    const Result r = run({"/usr/bin/python3", kScript, (root_ / "nothing_here").string()}, 60.0);
    EXPECT_NE(r.exit_code, 0);
    EXPECT_NE(r.output.find("nothing_here: no such directory"), std::string::npos) << r.output;
    EXPECT_EQ(r.output.find("Traceback"), std::string::npos) << r.output;
}

}  // namespace
