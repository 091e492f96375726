// The interactive flight review. A 3-run scenario-#2 batch (navigation filters, direct layout, with
// a scheduled air-data fault so that the run pages have a fault to mark) then `gdnav report`: review.html and
// review/run_NNNN.html are written (tools/report/review.py), and headless Chromium (Debian's /usr/bin/chromium driven
// by playwright-core, review_node/check_review.mjs) opens the run's and the batch's page with no JavaScript error and
// no network request, finds every figure drawn (track: true and estimated curves; errors: every error curve, the
// GNSS-loss line and the fault window; bands; the final-error scatter), screenshots both pages into
// <build>/tests/review_screenshots/, and follows a click on a scatter point to that run's page.
#include <gtest/gtest.h>
#include <yaml-cpp/yaml.h>

#include <algorithm>
#include <cstdint>
#include <filesystem>
#include <fstream>
#include <regex>
#include <set>
#include <sstream>
#include <vector>

#include "process_util.hpp"

using namespace gdnav::testing;
namespace fs = std::filesystem;

namespace {


// A real screenshot: PNG magic and more than a blank page's bytes.
void expect_screenshot(const fs::path& p) {
    ASSERT_TRUE(fs::exists(p)) << p;
    const std::string bytes = read_file(p);
    EXPECT_EQ(bytes.substr(1, 3), "PNG") << p;
    EXPECT_GT(bytes.size(), 100000u) << p;
}

int figure_value(const YAML::Node& page, const std::string& fig, const std::string& key) {
    const YAML::Node n = page["figures"][fig][key];
    return n ? n.as<int>() : -1;
}

}  // namespace

TEST(ReviewPages, ChromiumOpensRunAndBatchPagesWithoutErrorsAndTheyShowTrackAndErrors) {
    const fs::path dir = temp_dir("review-batch");
    const Result mc = run({kExe, "montecarlo", "--scenario", "2", "--runs", "3", "--jobs", "2", "--layout", "direct",
                           "--seed", "1", "--no-report", "--set",
                           "faults=[{at_s: 200, until_s: 230, target: sensors_air, kind: noise, fields: {tas_mps: 3}}]",
                           "--out", dir.string()},
                          240.0);
    ASSERT_EQ(mc.exit_code, 0) << mc.output;
    const Result rep = run({kExe, "report", dir.string()}, 240.0);
    ASSERT_EQ(rep.exit_code, 0) << rep.output;
    EXPECT_NE(rep.output.find("review.py: run page 3/3"), std::string::npos) << rep.output;  // progress

    const fs::path report = dir / "report";
    const fs::path batch_page = report / "review.html";
    ASSERT_TRUE(fs::exists(batch_page));
    for (int i = 0; i < 3; ++i) ASSERT_TRUE(fs::exists(report / "review" / ("run_000" + std::to_string(i) + ".html")));
    EXPECT_TRUE(fs::exists(report / "horizontal_nse.png"));  // the PNG figures stay

    // The batch page shows gdnav report's own tables: every table heading and the body rows of tables.md.
    const std::string html = read_file(batch_page);
    std::istringstream md(read_file(report / "tables.md"));
    std::string line;
    int headings = 0;
    while (std::getline(md, line))
        if (line.rfind("### ", 0) == 0) {
            ++headings;
            EXPECT_NE(html.find(line.substr(4)), std::string::npos) << line;
        }
    EXPECT_GE(headings, 4);
    // One copy of plotly.js in the report folder, loaded by every page with a relative address; no other script
    // file, nothing from the network (check_review.mjs below).
    std::vector<fs::path> libs;
    for (const auto& e : fs::recursive_directory_iterator(report))
        if (e.path().filename().string().rfind("plotly-", 0) == 0) libs.push_back(e.path());
    ASSERT_EQ(libs.size(), 1u);
    EXPECT_EQ(libs[0].parent_path(), report);
    const std::string lib = libs[0].filename().string();
    EXPECT_NE(html.find("<script id=\"plotly-js\" src=\"" + lib + "\">"), std::string::npos);
    const std::string run0 = read_file(report / "review" / "run_0000.html");
    EXPECT_NE(run0.find("<script id=\"plotly-js\" src=\"../" + lib + "\">"), std::string::npos);
    // The size budget of a 100-run report folder (docs/viewing.md "Size and speed"): the shared library, the batch
    // page and 100 run pages of this size stay under 30 MB.
    std::uintmax_t run_page_max = 0;
    for (int i = 0; i < 3; ++i) {
        const fs::path page = report / "review" / ("run_000" + std::to_string(i) + ".html");
        run_page_max = std::max(run_page_max, fs::file_size(page));
    }
    const std::uintmax_t hundred = fs::file_size(libs[0]) + fs::file_size(batch_page) + 100 * run_page_max;
    EXPECT_LT(hundred, 30'000'000u) << "run page " << run_page_max << " B, library " << fs::file_size(libs[0]) << " B";
    EXPECT_NE(run0.find("noise of sensors_air"), std::string::npos);  // the scheduled fault is listed
    EXPECT_NE(run0.find("GNSS lost"), std::string::npos);

    // review.py writes the run pages in worker processes (--jobs, default: the CPUs it may use); one worker or three
    // write the same bytes, the batch page included (its bands add the runs in run order).
    for (const char* jobs : {"1", "3"}) {
        const fs::path o = dir / (std::string("review_jobs_") + jobs);
        const Result r = run({"/usr/bin/python3", GDNAV_REVIEW_PY, dir.string(), "--out", o.string(), "--tables",
                              (report / "tables.md").string(), "--runs-csv", (report / "runs.csv").string(), "--jobs",
                              jobs},
                             120.0);
        ASSERT_EQ(r.exit_code, 0) << r.output;
    }
    for (const std::string f : {"review.html", "review/run_0000.html", "review/run_0002.html"}) {
        const std::string one = read_file(dir / "review_jobs_1" / f), three = read_file(dir / "review_jobs_3" / f);
        EXPECT_GT(one.size(), 20000u) << f;
        EXPECT_TRUE(one == three) << f << " differs between --jobs 1 and --jobs 3";
    }

    const fs::path shots = GDNAV_REVIEW_SHOT_DIR;
    fs::remove(shots / "review_run.png");
    fs::remove(shots / "review_batch.png");
    const std::string script = std::string(GDNAV_REVIEW_NODE_DIR) + "/check_review.mjs";
    const Result node = run({GDNAV_NODE, script, (report / "review" / "run_0001.html").string(), batch_page.string(),
                             shots.string()},
                            240.0);
    std::printf("%s\n", node.output.c_str());
    ASSERT_EQ(node.exit_code, 0) << node.output;
    const std::string json = node.output.substr(node.output.find("{\"pages\""));
    const YAML::Node res = YAML::Load(json);
    EXPECT_EQ(res["problems"].size(), 0u) << json;

    const YAML::Node runp = res["pages"]["run"];
    EXPECT_EQ(runp["ready"].as<int>(), 3) << json;           // track, errors, events
    EXPECT_GE(figure_value(runp, "track", "lines"), 2);      // the true and the estimated track
    EXPECT_GE(figure_value(runp, "errors", "lines"), 10);    // yaw, pitch, bank, |dr|, h, vN, vE, hor, cross, along
    EXPECT_GE(figure_value(runp, "errors", "shapes"), 2);    // the GNSS-loss line and the fault window
    EXPECT_GT(figure_value(runp, "events", "points"), 0);    // GNSS fixes and logged events
    const YAML::Node batchp = res["pages"]["batch"];
    EXPECT_EQ(batchp["ready"].as<int>(), 2) << json;          // bands, final errors
    EXPECT_EQ(figure_value(batchp, "bands", "fills"), 10);    // one mean +- sigma band per error curve
    EXPECT_EQ(figure_value(batchp, "final", "points"), 6);    // 3 runs in each of the two scatters
    std::set<std::string> links;
    for (const auto& l : batchp["links"]) links.insert(l.as<std::string>());
    for (int i = 0; i < 3; ++i) EXPECT_TRUE(links.count("review/run_000" + std::to_string(i) + ".html")) << json;
    EXPECT_TRUE(std::regex_match(res["clicked"]["url"].as<std::string>(), std::regex(R"(run_000[0-2]\.html)"))) << json;
    EXPECT_EQ(res["clicked"]["ready"].as<int>(), 3);

    expect_screenshot(shots / "review_run.png");
    expect_screenshot(shots / "review_batch.png");
    if (!::testing::Test::HasFailure()) fs::remove_all(dir);
}
