// Config fuzzer: every config file the paper scenarios read is mutated one value at a time (config_mutation.hpp) and
// the scenario validated in-process, exactly as `gdnav validate --scenario paper1|paper2` does
// (cli::validate_scenario).
//
// Files: config/scenarios/paper1.yaml and paper2.yaml and everything they read (aircraft, Earth magnetic model,
// autopilot, sensor suite, nav tuning, the baseline variant and the baseline grade files), plus the other nav variant
// files and sensor grade files, which the paper's comparison runs read through --variant / --grade (each checked
// through a copy of paper2 pointing at it). Each file gets the mutation kinds on leaves drawn by a seeded
// rnd::Stream, in a temporary copy of config/ (GDNAV_CONFIG_DIR).
//
// Outcome of each case:
//   rejected   ConfigError, one line (no other log line), naming the mutated file and the mutated key (for
//              `negative` and `huge`, a cross-check naming another key also counts, e.g. empty_kg must be below
//              full_kg, or the flight-physics trim failing, which names the aircraft file; for `garbage` the file
//              alone);
//   accepted   allowed only for: negative and huge numbers (inside the key's range), a deleted key that has a
//              documented default, and text replacing a free-text key (description, name); printed one per line;
//   failure    anything else: any other exception, a rejection naming the wrong file or key or taking more than
//              one line, an accepted NaN / inf / unknown key / wrong type / garbage file.
#include <gtest/gtest.h>
#include <spdlog/sinks/ostream_sink.h>
#include <spdlog/sinks/stdout_color_sinks.h>
#include <spdlog/spdlog.h>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <map>
#include <sstream>

#include "commands.hpp"
#include "config/config.hpp"
#include "config_mutation.hpp"

namespace fs = std::filesystem;
using namespace gdnav::testing::fuzz;

namespace {

constexpr std::uint64_t kSeed = 20240611;  // GDNAV_CONFIG_FUZZ_SEED / _ROUNDS (a multiplier) explore further

std::uint64_t env_u64(const char* name, std::uint64_t fallback) {
    const char* v = std::getenv(name);
    return v && *v ? std::strtoull(v, nullptr, 10) : fallback;
}

struct Target {
    std::string file;      // relative to config/
    std::string scenario;  // scenario name validated for it
    int rounds{1};         // rounds of the leaf kinds
};

struct Tally {
    int cases{0}, rejected{0}, accepted{0}, failed{0};
};

// The files paper1 and paper2 read, then the other variant and grade files through derived scenarios.
std::vector<Target> fuzz_targets(const fs::path& src, const fs::path& cfg) {
    std::vector<Target> targets{
        {"scenarios/paper1.yaml", "paper1", 2},   {"scenarios/paper2.yaml", "paper2", 2},
        {"aircraft/mugin.yaml", "paper2", 3},     {"earth/magnetic_wisconsin.yaml", "paper1", 1},
        {"control/mugin_autopilot.yaml", "paper1", 3}, {"sensors/suite.yaml", "paper2", 2},
        {"nav/tuning.yaml", "paper2", 3},         {"nav/variants/baseline.yaml", "paper1", 1},
    };
    for (const auto& e : fs::directory_iterator(src / "nav" / "variants")) {
        const std::string stem = e.path().stem().string();
        if (stem == "baseline") continue;
        write_derived_scenario(cfg, "fuzz_variant_" + stem,
                               {{"nav_att", "variant", "nav/variants/" + stem + ".yaml"},
                                {"nav_pos", "variant", "nav/variants/" + stem + ".yaml"}});
        targets.push_back({"nav/variants/" + stem + ".yaml", "fuzz_variant_" + stem, 1});
    }
    const std::map<std::string, std::pair<std::string, std::string>> grade_key{
        {"gyroscopes", {"sensors_inertial", "gyr_grade"}}, {"accelerometers", {"sensors_inertial", "acc_grade"}},
        {"magnetometers", {"sensors_magnetic", "grade"}},  {"air_data", {"sensors_air", "grade"}},
        {"atmospheric", {"sensors_atmospheric", "grade"}}, {"gnss", {"sensors_gnss", "grade"}}};
    for (const auto& [group, ck] : grade_key) {
        std::vector<std::string> grades;
        for (const auto& e : fs::directory_iterator(src / "sensors" / group))
            grades.push_back(e.path().stem().string());
        std::sort(grades.begin(), grades.end());
        for (const auto& g : grades) {
            const std::string name = "fuzz_grade_" + group + "_" + g;
            write_derived_scenario(cfg, name, {{ck.first, ck.second, g}});
            targets.push_back({"sensors/" + group + "/" + g + ".yaml", name, 1});
        }
    }
    return targets;
}

// What one validation of a mutated file gave: a config error, another exception, or acceptance.
struct Outcome {
    bool accepted{false};
    std::string error, other;
};

Outcome validate(const std::string& scenario, const gdnav::framework::ComponentRegistry& reg) {
    Outcome o;
    try {
        (void)gdnav::cli::validate_scenario(scenario, reg);
        o.accepted = true;
    } catch (const gdnav::config::ConfigError& e) {
        o.error = e.what();
    } catch (const std::exception& e) {
        o.other = e.what();
    }
    return o;
}

// The judgement of one case (see the file's comment): "" when it is legitimate, else what is wrong.
std::string judge(const Outcome& o, const Mutation& m, Kind kind, bool numeric_leaf, const std::string& file_path,
                  const std::string& logged) {
    if (!o.other.empty()) return "not a config error: " + o.other;
    if (o.accepted) return m.may_accept ? "" : "accepted";
    const bool one_line = o.error.find('\n') == std::string::npos && logged.empty();
    // The mutated file: as the error's origin, or named in the message of a cross-file check (the flight-physics
    // trim names the aircraft file).
    const bool names_file = o.error.find(file_path) != std::string::npos;
    bool names_key = kind == Kind::kGarbage || o.error.find("key '" + m.key + "'") != std::string::npos;
    if (!names_key && numeric_leaf && (kind == Kind::kNegative || kind == Kind::kHuge))
        names_key = o.error.find("key '") != std::string::npos;  // a cross-check with another key
    if (one_line && names_file && names_key) return "";
    return std::string("bad rejection") + (one_line ? "" : " (more than one line)") +
           (names_file ? "" : " (file not named)") + (names_key ? "" : " (key not named)") + ": " + o.error +
           (logged.empty() ? "" : " | logged: " + logged);
}

}  // namespace

TEST(ConfigFuzz, PaperScenarioFilesRejectEveryInvalidMutation) {
    gdnav::framework::ComponentRegistry reg;
    const fs::path tmp = private_config("cfg_fuzz", reg);
    const fs::path cfg = tmp / "config";

    // Everything logged during a validation (gdnav validate prints it: a rejection must be the only line).
    std::ostringstream log;
    auto logger = std::make_shared<spdlog::logger>("fuzz", std::make_shared<spdlog::sinks::ostream_sink_mt>(log));
    logger->set_level(spdlog::level::info);
    spdlog::set_default_logger(logger);

    const std::vector<Target> targets = fuzz_targets(fs::path(GDNAV_SOURCE_DIR) / "config", cfg);
    for (const auto& t : targets) {  // the unmutated copies validate
        const Outcome o = validate(t.scenario, reg);
        ASSERT_TRUE(o.accepted) << "unmutated scenario " << t.scenario << " does not validate: " << o.error << o.other;
    }

    std::map<std::string, Tally> tally;
    std::vector<std::string> accepted_lines, failures;
    std::size_t deleted_with_default = 0;
    const std::uint64_t seed = env_u64("GDNAV_CONFIG_FUZZ_SEED", kSeed);
    const int rounds_factor = static_cast<int>(env_u64("GDNAV_CONFIG_FUZZ_ROUNDS", 1));
    const auto t0 = std::chrono::steady_clock::now();

    for (const auto& t : targets) {
        const fs::path file = cfg / t.file;
        const std::string original = read_text(file);
        const YAML::Node doc = YAML::Load(original);
        const std::vector<Leaf> leaves = collect_leaves(doc);
        std::vector<Leaf> numeric;
        std::copy_if(leaves.begin(), leaves.end(), std::back_inserter(numeric), [](const Leaf& l) { return l.numeric; });
        ASSERT_FALSE(leaves.empty()) << t.file;
        gdnav::rnd::Stream rs = gdnav::rnd::Stream::derive(seed, 0, "config_fuzz/" + t.file);

        std::vector<Kind> kinds;
        for (int r = 0; r < t.rounds * rounds_factor; ++r)
            kinds.insert(kinds.end(), std::begin(kLeafKinds), std::end(kLeafKinds));
        kinds.push_back(Kind::kGarbage);

        for (const Kind kind : kinds) {
            // Number kinds go to numeric leaves where the file has any; the others to any leaf.
            const auto& pool = number_kind(kind) && !numeric.empty() ? numeric : leaves;
            const Leaf& leaf = pool[static_cast<std::size_t>(rs.uniform_int(0, static_cast<int>(pool.size()) - 1))];
            const Mutation m = mutate(doc, original, leaf, kind, rs);
            write_text(file, m.text);
            log.str("");
            const Outcome o = validate(t.scenario, reg);
            write_text(file, original);

            Tally& tl = tally[t.file];
            ++tl.cases;
            const std::string where = t.file + " [" + kind_name(kind) + "] " + m.detail;
            const std::string wrong = judge(o, m, kind, leaf.numeric, file.string(), log.str());
            if (!wrong.empty()) {
                failures.push_back(where + ": " + wrong);
                ++tl.failed;
            } else if (o.accepted) {
                ++tl.accepted;
                if (kind == Kind::kDelete) ++deleted_with_default;
                accepted_lines.push_back(where);
            } else {
                ++tl.rejected;
            }
        }
    }
    const double wall_s = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();

    Tally total;
    std::printf("\nconfig fuzzer, seed %llu: one mutation per case, validated as gdnav validate\n",
                static_cast<unsigned long long>(seed));
    std::printf("%-42s %6s %9s %9s %7s\n", "file", "cases", "rejected", "accepted", "failed");
    for (const auto& [f, tl] : tally) {
        std::printf("%-42s %6d %9d %9d %7d\n", f.c_str(), tl.cases, tl.rejected, tl.accepted, tl.failed);
        total.cases += tl.cases;
        total.rejected += tl.rejected;
        total.accepted += tl.accepted;
        total.failed += tl.failed;
    }
    std::printf("%-42s %6d %9d %9d %7d\n", "total", total.cases, total.rejected, total.accepted, total.failed);
    std::printf("%.1f s. Accepted cases (each legitimate: a negative or huge number inside the key's range, a deleted "
                "key that has a documented default (%zu), or text in a free-text key):\n",
                wall_s, deleted_with_default);
    for (const auto& a : accepted_lines) std::printf("  accepted: %s\n", a.c_str());
    for (const auto& f : failures) std::printf("  FAILED: %s\n", f.c_str());
    std::fflush(stdout);

    EXPECT_TRUE(failures.empty()) << failures.size() << " failures (listed above)";
    EXPECT_GE(total.cases, 200);
    spdlog::set_default_logger(spdlog::stderr_color_mt("fuzz_done"));
    fs::remove_all(tmp);
}
