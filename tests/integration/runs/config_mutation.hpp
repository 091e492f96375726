// One-value mutations of a YAML config file, for the config fuzzer (config_fuzz_test.cpp): the leaves of a
// document, the mutation kinds, and a private copy of config/ in which the mutated scenarios are validated.
#pragma once

#include <yaml-cpp/yaml.h>

#include <filesystem>
#include <string>
#include <tuple>
#include <variant>
#include <vector>

#include "framework/registry.hpp"
#include "random/stream.hpp"

namespace gdnav::testing::fuzz {

enum class Kind { kNan, kInf, kNegInf, kNegative, kHuge, kText, kList, kDelete, kUnknownKey, kGarbage };
// The kinds applied to a leaf (every kind but garbage, which replaces the whole file).
inline constexpr Kind kLeafKinds[] = {Kind::kNan,      Kind::kInf,  Kind::kNegInf, Kind::kNegative,  Kind::kHuge,
                                      Kind::kText,     Kind::kList, Kind::kDelete, Kind::kUnknownKey};

const char* kind_name(Kind k);
// NaN, ±inf, negative and huge: kinds that replace a number.
bool number_kind(Kind k);

using Step = std::variant<std::string, std::size_t>;  // map key or list index
struct Leaf {
    std::vector<Step> path;
    std::string value;
    bool numeric{false};
};

// Every scalar of the document, in document order.
std::vector<Leaf> collect_leaves(const YAML::Node& doc);

// One mutated file: its text, the mutated key path ("" for garbage), what changed, and whether accepting it is
// legitimate (a finite number in range, a key with a default, any text for a free-text key).
struct Mutation {
    std::string text;
    std::string key;
    std::string detail;
    bool may_accept{false};
};

// Applies `kind` to `leaf` of `doc` (`original` is the file's text, for garbage); draws from `rs` for garbage only.
Mutation mutate(const YAML::Node& doc, const std::string& original, const Leaf& leaf, Kind kind, rnd::Stream& rs);

std::string read_text(const std::filesystem::path& p);
void write_text(const std::filesystem::path& p, const std::string& s);

// A copy of paper2 whose components take `sets` (component -> key -> value): used to reach variant and grade files
// that the paper scenarios read only through --variant / --grade.
void write_derived_scenario(const std::filesystem::path& cfg, const std::string& name,
                            const std::vector<std::tuple<std::string, std::string, std::string>>& sets);

// A private copy of config/ in a temporary directory, read by the validator through GDNAV_CONFIG_DIR, with every
// component type registered in `reg`. Returns the temporary directory (config/ is below it).
std::filesystem::path private_config(const std::string& tag, framework::ComponentRegistry& reg);

}  // namespace gdnav::testing::fuzz
