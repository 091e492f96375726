// gdnav bench --json FILE (issue 13, item 4): the file is produced and is well-formed JSON with the expected keys
// (checked with Python's json module); the figures themselves are not asserted.
#include <gtest/gtest.h>

#include "process_util.hpp"

using namespace gdnav::testing;
namespace fs = std::filesystem;

TEST(BenchJson, WritesWellFormedFiguresWithTheMachine) {
    const fs::path dir = temp_dir("bench_json");
    const fs::path json = dir / "bench.json";
    const Result r = run({GDNAV_GDNAV_EXE, "bench", "--scenario", "default", "--steps", "300", "--layouts", "direct",
                          "--mc-runs", "1", "--mc-steps", "300", "--mc-jobs", "1", "--json", json.string()},
                         180.0);
    ASSERT_EQ(r.exit_code, 0) << r.output;
    ASSERT_TRUE(fs::exists(json)) << r.output;
    const char* check = R"(
import json, sys
d = json.load(open(sys.argv[1]))
for k in ("format", "date_utc", "git_commit", "git_dirty", "machine", "scenario", "steps", "layouts", "component_us_per_step", "montecarlo"):
    assert k in d, k
assert d["format"] == "gdnav-bench"
assert d["machine"]["cores"] >= 1 and d["machine"]["cpu_model"]
assert d["layouts"]["direct"]["steps_per_s"] > 0 and "x_real_time" in d["layouts"]["direct"]
for c in ("flight_physics", "nav_att", "nav_pos", "nav_air", "control", "guidance"):
    assert d["component_us_per_step"][c] >= 0, c
mc = d["montecarlo"]["scenarios"]
assert set(mc) == {"1", "2"}
for s in mc.values():
    assert s["runs_per_minute"] > 0 and s["steps_per_run_measured"] == 300 and s["steps_per_run_full"] > 300
print("json ok")
)";
    const Result py = run({"/usr/bin/python3", "-c", check, json.string()}, 60.0);
    EXPECT_EQ(py.exit_code, 0) << py.output << "\n" << read_file(json);
    EXPECT_NE(py.output.find("json ok"), std::string::npos) << py.output;
    EXPECT_NE(r.output.find("runs/min"), std::string::npos) << r.output;
}
