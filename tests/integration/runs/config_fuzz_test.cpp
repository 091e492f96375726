// Config fuzzer (issue 11 item 5): every config file the paper scenarios read is mutated one value at a time and the
// scenario validated in-process, exactly as `gdnav validate --scenario paper1|paper2` does (app::validate_scenario).
//
// Files: config/scenarios/paper1.yaml and paper2.yaml and everything they read (aircraft, Earth magnetic model,
// autopilot, sensor suite, nav tuning, the baseline variant and the baseline grade files), plus the other nav variant
// files and sensor grade files, which the paper's comparison runs read through --variant / --grade (each checked
// through a copy of paper2 pointing at it). Each file gets the mutation kinds below on leaves drawn by a seeded
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
#include <yaml-cpp/yaml.h>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <map>
#include <sstream>
#include <string>
#include <tuple>
#include <variant>
#include <vector>

#include "commands.hpp"
#include "config/config.hpp"
#include "process_util.hpp"
#include "random/stream.hpp"
#include "register_components.hpp"
#include "framework/topic_types.hpp"

namespace fs = std::filesystem;

namespace {

constexpr std::uint64_t kSeed = 20240611;  // GDNAV_CONFIG_FUZZ_SEED / _ROUNDS (a multiplier) explore further

std::uint64_t env_u64(const char* name, std::uint64_t fallback) {
    const char* v = std::getenv(name);
    return v && *v ? std::strtoull(v, nullptr, 10) : fallback;
}

enum class Kind { kNan, kInf, kNegInf, kNegative, kHuge, kText, kList, kDelete, kUnknownKey, kGarbage };
constexpr Kind kLeafKinds[] = {Kind::kNan,      Kind::kInf,  Kind::kNegInf, Kind::kNegative,  Kind::kHuge,
                               Kind::kText,     Kind::kList, Kind::kDelete, Kind::kUnknownKey};

const char* kind_name(Kind k) {
    switch (k) {
        case Kind::kNan: return "nan";
        case Kind::kInf: return "inf";
        case Kind::kNegInf: return "-inf";
        case Kind::kNegative: return "negative";
        case Kind::kHuge: return "huge";
        case Kind::kText: return "text";
        case Kind::kList: return "list";
        case Kind::kDelete: return "delete";
        case Kind::kUnknownKey: return "unknown-key";
        case Kind::kGarbage: return "garbage";
    }
    return "?";
}

// Keys whose value is free text: any scalar is valid there.
bool free_text_key(const std::string& key) { return key == "description" || key == "name"; }

using Step = std::variant<std::string, std::size_t>;  // map key or list index
struct Leaf {
    std::vector<Step> path;
    std::string value;
    bool numeric{false};
};

std::string path_str(const std::vector<Step>& p, std::size_t n) {
    std::string s;
    for (std::size_t i = 0; i < n; ++i) {
        if (const auto* k = std::get_if<std::string>(&p[i]))
            s += (s.empty() ? "" : ".") + *k;
        else
            s += "[" + std::to_string(std::get<std::size_t>(p[i])) + "]";
    }
    return s;
}

bool is_number(const YAML::Node& n) {
    const std::string& s = n.Scalar();
    if (s == "true" || s == "false" || s.empty()) return false;
    try {
        (void)n.as<double>();
        return true;
    } catch (const YAML::Exception&) {
        return false;
    }
}

void collect(const YAML::Node& n, std::vector<Step>& path, std::vector<Leaf>& out) {
    if (n.IsMap()) {
        for (const auto& kv : n) {
            path.emplace_back(kv.first.Scalar());
            collect(kv.second, path, out);
            path.pop_back();
        }
    } else if (n.IsSequence()) {
        for (std::size_t i = 0; i < n.size(); ++i) {
            path.emplace_back(i);
            collect(n[i], path, out);
            path.pop_back();
        }
    } else if (n.IsScalar()) {
        out.push_back({path, n.Scalar(), is_number(n)});
    }
}

// The node at path[0, n) (yaml-cpp nodes are handles: assigning through it changes the document).
YAML::Node at(YAML::Node root, const std::vector<Step>& p, std::size_t n) {
    YAML::Node cur = root;
    for (std::size_t i = 0; i < n; ++i) {
        if (const auto* k = std::get_if<std::string>(&p[i]))
            cur.reset(cur[*k]);
        else
            cur.reset(cur[std::get<std::size_t>(p[i])]);
    }
    return cur;
}

// Index of the last map key in the path: deleting a list element deletes the list, an unknown key goes next to it.
std::size_t last_key(const std::vector<Step>& p) {
    for (std::size_t i = p.size(); i-- > 0;)
        if (std::holds_alternative<std::string>(p[i])) return i;
    return 0;
}

std::string num_text(double v) {
    std::ostringstream os;
    os.precision(15);  // the file values have fewer digits: -0.27576, not -0.27576000000000001
    os << v;
    return os.str();
}

struct Target {
    std::string file;      // relative to config/
    std::string scenario;  // scenario name validated for it
    int rounds{1};         // rounds of the leaf kinds
};

struct Case {
    std::string file;
    Kind kind;
    std::string key;  // mutated key path ("" for garbage)
    std::string detail;
};

struct Tally {
    int cases{0}, rejected{0}, accepted{0}, failed{0};
};

std::string read_text(const fs::path& p) {
    std::ifstream in(p, std::ios::binary);
    std::stringstream ss;
    ss << in.rdbuf();
    return ss.str();
}

void write_text(const fs::path& p, const std::string& s) { std::ofstream(p, std::ios::binary) << s; }

std::string emit(const YAML::Node& n) {
    YAML::Emitter em;
    em << n;
    return std::string(em.c_str()) + "\n";
}

// A copy of paper2 whose components take `sets` (component -> key -> value): used to reach variant and grade files
// that the paper scenarios read only through --variant / --grade.
void write_derived_scenario(const fs::path& cfg, const std::string& name,
                            const std::vector<std::tuple<std::string, std::string, std::string>>& sets) {
    YAML::Node doc = YAML::Load(read_text(cfg / "scenarios" / "paper2.yaml"));
    for (const auto& [comp, key, value] : sets) doc["components"][comp][key] = value;
    write_text(cfg / "scenarios" / (name + ".yaml"), emit(doc));
}

// A private copy of config/ in a temporary directory, read by the validator through GDNAV_CONFIG_DIR, with every
// component type registered in `reg`. Returns the temporary directory (config/ is below it).
fs::path private_config(const std::string& tag, gdnav::runtime::ComponentRegistry& reg) {
    const fs::path tmp = gdnav::testing::temp_dir(tag);
    fs::copy(fs::path(GDNAV_SOURCE_DIR) / "config", tmp / "config", fs::copy_options::recursive);
    ::setenv("GDNAV_CONFIG_DIR", (tmp / "config").c_str(), 1);
    gdnav::runtime::register_gdnav_topics();
    gdnav::app::register_all_components(reg);
    return tmp;
}

}  // namespace

TEST(ConfigFuzz, PaperScenarioFilesRejectEveryInvalidMutation) {
    gdnav::runtime::ComponentRegistry reg;
    const fs::path tmp = private_config("cfg_fuzz", reg);
    const fs::path src = fs::path(GDNAV_SOURCE_DIR) / "config";
    const fs::path cfg = tmp / "config";

    // Everything logged during a validation (gdnav validate prints it: a rejection must be the only line).
    std::ostringstream log;
    auto logger = std::make_shared<spdlog::logger>("fuzz", std::make_shared<spdlog::sinks::ostream_sink_mt>(log));
    logger->set_level(spdlog::level::info);
    spdlog::set_default_logger(logger);

    // Targets: the files paper1 and paper2 read, then the other variant and grade files through derived scenarios.
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

    // The unmutated copies validate.
    for (const auto& t : targets) {
        log.str("");
        try {
            (void)gdnav::app::validate_scenario(t.scenario, reg);
        } catch (const std::exception& e) {
            FAIL() << "unmutated scenario " << t.scenario << " does not validate: " << e.what();
        }
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
        std::vector<Leaf> leaves, numeric;
        std::vector<Step> path;
        collect(doc, path, leaves);
        for (const auto& l : leaves)
            if (l.numeric) numeric.push_back(l);
        ASSERT_FALSE(leaves.empty()) << t.file;
        gdnav::rnd::Stream rs = gdnav::rnd::Stream::derive(seed, 0, "config_fuzz/" + t.file);

        std::vector<Kind> kinds;
        for (int r = 0; r < t.rounds * rounds_factor; ++r)
            kinds.insert(kinds.end(), std::begin(kLeafKinds), std::end(kLeafKinds));
        kinds.push_back(Kind::kGarbage);

        for (const Kind kind : kinds) {
            // Number kinds go to numeric leaves where the file has any; the others to any leaf.
            const bool number_kind = kind == Kind::kNan || kind == Kind::kInf || kind == Kind::kNegInf ||
                                     kind == Kind::kNegative || kind == Kind::kHuge;
            const auto& pool = number_kind && !numeric.empty() ? numeric : leaves;
            const Leaf& leaf = pool[static_cast<std::size_t>(rs.uniform_int(0, static_cast<int>(pool.size()) - 1))];
            const std::size_t lk = last_key(leaf.path);
            const std::string leaf_key = std::get<std::string>(leaf.path[lk]);
            Case c{t.file, kind, path_str(leaf.path, lk + 1), ""};
            bool may_accept = false;
            std::string text;

            if (kind == Kind::kGarbage) {
                c.key.clear();
                const int g = rs.uniform_int(0, 2);
                if (g == 0) {
                    const int n = rs.uniform_int(1, 200);
                    for (int i = 0; i < n; ++i) text.push_back(static_cast<char>(rs.uniform_int(0, 255)));
                    c.detail = std::to_string(n) + " random bytes";
                } else if (g == 1) {
                    const int cut = rs.uniform_int(1, static_cast<int>(original.size()) - 1);
                    text = original.substr(0, static_cast<std::size_t>(cut)) + "\n]: {\n";
                    c.detail = "first " + std::to_string(cut) + " bytes, then ']: {'";
                } else {
                    text = "- just\n- a list\n";
                    c.detail = "a list instead of a mapping";
                }
            } else {
                YAML::Node root = YAML::Clone(doc);
                YAML::Node node = at(root, leaf.path, leaf.path.size());
                const double v = leaf.numeric ? node.as<double>() : 0.0;
                switch (kind) {
                    case Kind::kNan: node = ".nan"; break;
                    case Kind::kInf: node = ".inf"; break;
                    case Kind::kNegInf: node = "-.inf"; break;
                    case Kind::kNegative: node = num_text(v > 0 ? -v : v < 0 ? v * 1e6 : -1.0); break;
                    case Kind::kHuge: node = "1.0e+300"; break;
                    case Kind::kText: node = "fuzz text"; break;
                    case Kind::kList: {
                        YAML::Node l(YAML::NodeType::Sequence);
                        l.push_back(1);
                        l.push_back("two");
                        node = l;
                        break;
                    }
                    case Kind::kDelete: at(root, leaf.path, lk).remove(leaf_key); break;
                    case Kind::kUnknownKey: {
                        at(root, leaf.path, lk)["fuzz_unknown_key"] = 1;
                        c.key = path_str(leaf.path, lk);
                        c.key += (c.key.empty() ? "" : ".") + std::string("fuzz_unknown_key");
                        break;
                    }
                    case Kind::kGarbage: break;
                }
                if (kind != Kind::kDelete && kind != Kind::kUnknownKey)
                    c.detail = path_str(leaf.path, leaf.path.size()) + ": " + leaf.value + " -> " +
                               (kind == Kind::kList ? "[1, two]" : node.Scalar());
                else
                    c.detail = kind == Kind::kDelete ? c.key + " removed" : c.key + " added";
                // Which acceptances are legitimate (printed): a finite number in range; a key with a default; any
                // text for a free-text key; a non-number replacing a string leaf is judged like text.
                if (leaf.numeric && (kind == Kind::kNegative || kind == Kind::kHuge)) may_accept = true;
                if (kind == Kind::kDelete) may_accept = true;
                if (!leaf.numeric && (number_kind || kind == Kind::kText) && free_text_key(leaf_key)) may_accept = true;
                text = emit(root);
            }

            write_text(file, text);
            log.str("");
            std::string error;
            std::string other;
            bool accepted = false;
            try {
                (void)gdnav::app::validate_scenario(t.scenario, reg);
                accepted = true;
            } catch (const gdnav::config::ConfigError& e) {
                error = e.what();
            } catch (const std::exception& e) {
                other = e.what();
            }
            write_text(file, original);

            Tally& tl = tally[t.file];
            ++tl.cases;
            const std::string where = t.file + " [" + kind_name(kind) + "] " + c.detail;
            if (!other.empty()) {
                failures.push_back(where + ": not a config error: " + other);
                ++tl.failed;
            } else if (accepted) {
                if (may_accept) {
                    ++tl.accepted;
                    if (kind == Kind::kDelete) ++deleted_with_default;
                    accepted_lines.push_back(where);
                } else {
                    failures.push_back(where + ": accepted");
                    ++tl.failed;
                }
            } else {
                const std::string logged = log.str();
                const bool one_line = error.find('\n') == std::string::npos && logged.empty();
                // The mutated file: as the error's origin, or named in the message of a cross-file check (the
                // flight-physics trim names the aircraft file).
                const bool names_file = error.find((cfg / t.file).string()) != std::string::npos;
                bool names_key = kind == Kind::kGarbage || error.find("key '" + c.key + "'") != std::string::npos;
                if (!names_key && leaf.numeric && (kind == Kind::kNegative || kind == Kind::kHuge))
                    names_key = error.find("key '") != std::string::npos;  // a cross-check with another key
                if (one_line && names_file && names_key) {
                    ++tl.rejected;
                } else {
                    failures.push_back(where + ": bad rejection" + (one_line ? "" : " (more than one line)") +
                                       (names_file ? "" : " (file not named)") + (names_key ? "" : " (key not named)") +
                                       ": " + error + (logged.empty() ? "" : " | logged: " + logged));
                    ++tl.failed;
                }
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

// The finding of the user trial (issue 11 item 5): unknown keys in config/nav/tuning.yaml and the variant files were
// accepted when they lay outside the section a nav component reads. Each file is now validated whole.
TEST(ConfigFuzz, NavTuningAndVariantFilesRejectUnknownKeysAnywhere) {
    gdnav::runtime::ComponentRegistry reg;
    const fs::path tmp = private_config("cfg_nav", reg);
    const fs::path cfg = tmp / "config";

    struct NavCase {
        std::string file, append, key;
    };
    const std::vector<NavCase> cases{
        {"nav/tuning.yaml", "atitude: {dt_s: 0.01}\n", "atitude"},
        {"nav/tuning.yaml", "extra: 1\n", "extra"},
        {"nav/variants/baseline.yaml", "air: {model: x}\n", "air"},
        {"nav/variants/hor_double_integration.yaml", "postion: {horizontal: frozen_wind}\n", "postion"},
    };
    for (const auto& c : cases) {
        SCOPED_TRACE(c.file + " + " + c.append);
        const fs::path file = cfg / c.file;
        const std::string original = read_text(file);
        write_text(file, original + c.append);
        const bool variant = c.file != "nav/tuning.yaml";
        if (variant)
            write_derived_scenario(cfg, "fuzz_nav", {{"nav_att", "variant", c.file}, {"nav_pos", "variant", c.file}});
        std::string error;
        try {
            (void)gdnav::app::validate_scenario(variant ? "fuzz_nav" : "paper2", reg);
        } catch (const gdnav::config::ConfigError& e) {
            error = e.what();
        }
        write_text(file, original);
        EXPECT_NE(error.find(file.string() + ": key '" + c.key + "': unknown key"), std::string::npos) << error;
    }
    fs::remove_all(tmp);
}
