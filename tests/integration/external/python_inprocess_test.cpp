// In-process Python members (common/client/embed, docs/python.md "In-process members"): the example's member class
// run inside gdnav records the same topics, bit for bit, as the same class run as an external Python process; a
// 3-run direct-layout batch with it completes; and each bad member (missing file, syntax error, missing class,
// wrong port, an exception in the constructor or in a step) is one line naming the file. DDS domains 170-174.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include "launch/member_process.hpp"
#include "process_util.hpp"

using namespace gdnav::testing;
namespace fs = std::filesystem;

namespace {

const std::string kExample = GDNAV_SOURCE_DIR "/examples/python/complementary_attitude.py";
const char* const kSteps = "3000";  // 30 s from t0 = -50 s: alignment, initialisation, the first climb

std::string member_set(const std::string& file, const std::string& cls) {
    return "run.members={nav_att: {python: {file: " + file + ", class: " + cls + "}}}";
}

std::vector<std::string> gdnav_run(const std::string& layout, const fs::path& out, std::vector<std::string> more) {
    std::vector<std::string> a{GDNAV_GDNAV_EXE, "run", "--scenario", "paper2", "--seed", "1", "--layout", layout,
                               "--steps", kSteps, "--out", out.string()};
    a.insert(a.end(), more.begin(), more.end());
    return a;
}

// The last non-empty line of a log.
std::string last_line(const std::string& log) {
    std::string s = log.substr(0, log.find_last_not_of('\n') + 1);
    return s.substr(s.rfind('\n') + 1);
}

// Lines logged at error level ("] error: " as gdnav's log pattern writes the level).
int error_lines(const std::string& log) {
    int n = 0;
    for (std::size_t p = log.find("] error: "); p != std::string::npos; p = log.find("] error: ", p + 1)) ++n;
    return n;
}

}  // namespace

TEST(PythonInProcess, RecordsTheSameTopicsAsTheExternalMember) {
    // External: composed run waiting for nav_att, the example started as its own Python process.
    const fs::path ext = temp_dir("pyinproc-ext");
    const PairResult e = run_pair(gdnav_run("composed", ext, {"--external", "nav_att", "--domain", "170", "--record",
                                                              "all"}),
                                  {"/usr/bin/env", "PYTHONPATH=" GDNAV_PYTHON_MODULE_DIR, GDNAV_PYTHON_EXE, kExample,
                                   "--domain", "170"},
                                  ext, 120.0);
    ASSERT_EQ(e.run_code, 0) << e.run_log << "\n--- member:\n" << e.member_log;
    const auto want = read_digests(ext);
    ASSERT_TRUE(want.count("gdnav/AttitudeEstimate")) << read_file(ext / "record" / "digest.yaml");

    // In process: the same class, direct layout (the member in the executor's thread) and composed (in the DDS
    // host's threads).
    const std::string set = member_set(kExample, "ComplementaryAttitude");
    const fs::path direct = temp_dir("pyinproc-direct");
    const Result d = run(gdnav_run("direct", direct, {"--record", "all", "--set", set}), 120.0);
    ASSERT_EQ(d.exit_code, 0) << d.output;
    EXPECT_NE(d.output.find("Python step callback (in process), 3000 steps"), std::string::npos) << d.output;
    EXPECT_EQ(read_digests(direct), want) << read_file(direct / "record" / "digest.yaml");
    // run.yaml names the class's file and records its SHA-256, as processes.yaml does for a started member.
    const std::string sha = "sha256: " + gdnav::launch::sha256_of_file(kExample);
    EXPECT_NE(read_file(direct / "run.yaml").find("type: python_member"), std::string::npos);
    EXPECT_NE(read_file(direct / "run.yaml").find(sha), std::string::npos) << read_file(direct / "run.yaml");

    const fs::path composed = temp_dir("pyinproc-composed");
    const Result c = run(gdnav_run("composed", composed, {"--record", "all", "--domain", "171", "--set", set}), 120.0);
    ASSERT_EQ(c.exit_code, 0) << c.output;
    EXPECT_EQ(read_digests(composed), want) << read_file(composed / "record" / "digest.yaml");
    EXPECT_NE(read_file(composed / "run.yaml").find(sha), std::string::npos) << read_file(composed / "run.yaml");
}

TEST(PythonInProcess, MonteCarloBatchInDirectLayout) {
    const fs::path out = temp_dir("pyinproc-mc");
    const Result r = run({GDNAV_GDNAV_EXE, "montecarlo", "--scenario", "2", "--runs", "3", "--jobs", "2", "--layout",
                          "direct", "--steps", "2000", "--no-report", "--set",
                          member_set(kExample, "ComplementaryAttitude"), "--out", out.string()},
                         300.0);
    ASSERT_EQ(r.exit_code, 0) << r.output;
    for (const char* run : {"run_0000", "run_0001", "run_0002"}) {
        EXPECT_TRUE(fs::exists(out / "runs" / run / "metrics.yaml")) << run << "\n" << r.output;
        EXPECT_NE(read_file(out / "runs" / run / "log.txt").find("Python step callback (in process), 2000 steps"),
                  std::string::npos)
            << read_file(out / "runs" / run / "log.txt");
    }
}

TEST(PythonInProcess, BadMembersAreOneLineNamingTheFile) {
    const fs::path dir = temp_dir("pyinproc-bad");
    fs::create_directories(dir);
    const auto write = [&](const std::string& name, const std::string& text) {
        std::ofstream(dir / name) << text;
        return (dir / name).string();
    };
    const std::string ok_head = "import gdnav_client as g\n";
    struct Case {
        std::string file, cls, expect;
        int code;
    };
    const std::vector<Case> cases{
        {(dir / "missing.py").string(), "C", "missing.py: no such file", 2},
        {write("syntax.py", ok_head + "class C:\n    def __init__(self, m)\n        pass\n"), "C",
         "syntax.py:3: SyntaxError", 2},
        {write("noclass.py", ok_head + "class Other:\n    pass\n"), "C",
         "noclass.py: no class 'C' (classes defined there: Other)", 2},
        {write("wrongport.py", ok_head + "class C:\n    def __init__(self, m):\n        self.o = "
                                         "m.output('gdnav/PositionEstimate')\n    def step(self, k, t_s):\n        "
                                         "pass\n"),
         "C", "are not those of the member it replaces", 2},
        {write("unknowntopic.py", ok_head + "class C:\n    def __init__(self, m):\n        self.i = "
                                            "m.input('gdnav/NoSuchTopic')\n    def step(self, k, t_s):\n"
                                            "        pass\n"),
         "C", "unknowntopic.py:4: ValueError: unknown topic 'gdnav/NoSuchTopic'", 2},
        {write("nostep.py", ok_head + "class C:\n    def __init__(self, m):\n        self.o = "
                                      "m.output('gdnav/AttitudeEstimate')\n"),
         "C", "class C has no method step(self, k, t_s)", 2},
        {write("raises.py", ok_head + "class C:\n    def __init__(self, m):\n        self.o = "
                                      "m.output('gdnav/AttitudeEstimate')\n    def step(self, k, t_s):\n        if k "
                                      "== 30:\n            1 / 0\n"),
         "C", "Python exception in the step callback: ZeroDivisionError: division by zero (", 1},
    };
    for (const Case& c : cases) {
        const fs::path out = dir / ("out-" + fs::path(c.file).stem().string());
        const Result r = run(gdnav_run("direct", out, {"--set", member_set(c.file, c.cls)}), 60.0);
        EXPECT_EQ(r.exit_code, c.code) << c.file << "\n" << r.output;
        const std::string last = last_line(r.output);
        EXPECT_NE(last.find(c.expect), std::string::npos) << c.file << "\n" << r.output;
        EXPECT_NE(last.find(c.file), std::string::npos) << c.file << "\n" << r.output;
        if (c.code == 2) {
            EXPECT_EQ(error_lines(r.output), 1) << c.file << "\n" << r.output;
        }
    }
}
