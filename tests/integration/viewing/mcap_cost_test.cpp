// Size and cost of a recording, printed (not asserted; a study of about 20 s, CTest label `study`): MCAP bytes per
// simulated hour of scenario #1 with the default recorded topics (--record default: the five sensor topics), with
// Truth, with the viewer channels and with every topic, and the run's steps/s with and without the recorder (direct
// layout). `ctest -R Mcap.SizePerSimulatedHour -V` prints them (docs/viewing.md).
#include <gtest/gtest.h>
#include <sys/resource.h>

#include <algorithm>
#include <filesystem>
#include <regex>
#include <string>
#include <vector>

#include "process_util.hpp"

using namespace gdnav::testing;
namespace fs = std::filesystem;

namespace {
// steps/s of a direct run, from its "run complete: N steps in X s (Y steps/s" line.
double steps_per_s(const Result& r) {
    std::smatch m;
    if (!std::regex_search(r.output, m, std::regex(R"(run complete: \d+ steps in [0-9.]+ s \((\d+) steps/s)")))
        return 0.0;
    return std::stod(m[1]);
}

// CPU seconds (user + system, every thread) of the children waited for so far.
double children_cpu_s() {
    rusage u{};
    getrusage(RUSAGE_CHILDREN, &u);
    return static_cast<double>(u.ru_utime.tv_sec + u.ru_stime.tv_sec) +
           1e-6 * static_cast<double>(u.ru_utime.tv_usec + u.ru_stime.tv_usec);
}
}  // namespace

TEST(Mcap, SizePerSimulatedHourAndRecordingCostArePrinted) {
    // Scenario #1 (paper1), seed 1, 40 000 steps (400 s of its 3 850 s), direct layout; the cases interleaved, three
    // rounds, best steps/s kept (the machine is shared).
    const std::string steps = "40000";
    const double dt_s = 0.01;
    struct Case {
        const char* name;
        std::vector<std::string> extra;
        double best{0.0};
        double cpu_s{1e300};  // least CPU time of a run (whole process: start-up, every thread)
        std::uintmax_t bytes{0};
    };
    std::vector<Case> cases{{"no recorder", {}},
                            {"--record default", {"--record", "default"}},
                            {"default,Truth", {"--record", "default,Truth"}},
                            {"default,viewer", {"--record", "default,viewer"}},  // + the viewer channels (10 Hz)
                            {"--record all", {"--record", "all"}}};
    for (int rep = 0; rep < 3; ++rep)
        for (auto& c : cases) {
            const fs::path out = temp_dir("mcap-size");
            std::vector<std::string> argv{kExe, "run", "--scenario", "paper1", "--seed", "1", "--steps", steps,
                                          "--layout", "direct", "--out", out.string()};
            argv.insert(argv.end(), c.extra.begin(), c.extra.end());
            const double cpu0 = children_cpu_s();
            const Result r = run(argv, 300.0);
            c.cpu_s = std::min(c.cpu_s, children_cpu_s() - cpu0);
            ASSERT_EQ(r.exit_code, 0) << r.output;
            const double s = steps_per_s(r);
            ASSERT_GT(s, 0.0) << r.output;
            c.best = std::max(c.best, s);
            if (!c.extra.empty()) c.bytes = fs::file_size(out / "record" / "run.mcap");
            fs::remove_all(out);
        }
    const double hours = std::stod(steps) * dt_s / 3600.0;
    std::printf("scenario #1, %s steps (%.0f s simulated), direct layout, best of 3:\n", steps.c_str(), hours * 3600.0);
    const double n = std::stod(steps);
    for (const auto& c : cases) {
        std::printf("  %-17s %8.0f steps/s, CPU %6.2f us/step", c.name, c.best, 1e6 * c.cpu_s / n);
        if (c.bytes) {
            std::printf("  (wall %+.1f %%, CPU %+.1f %%)  MCAP %ju bytes = %.1f MB per simulated hour",
                        100.0 * (cases[0].best / c.best - 1.0), 100.0 * (c.cpu_s / cases[0].cpu_s - 1.0), c.bytes,
                        static_cast<double>(c.bytes) / hours / 1e6);
        }
        std::printf("\n");
    }
    std::printf("targets: <= 100 MB per simulated hour with --record default (the five sensor topics); recording cost "
                "within 10 %%\n");
}
