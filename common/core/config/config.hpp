#pragma once
// YAML configuration with validation. Every read names its key and allowed range; a bad file or value throws
// ConfigError with one line naming the file, the key and what is allowed. `finish()` rejects keys nobody read
// (typos), so a config is fully validated by constructing and configuring its components before anything starts.
// Numbers are always finite: NaN, .inf and -.inf are rejected by every numeric getter whatever the range. Parsing
// rejects duplicate keys and keys that are not plain scalars. A file that has several sections read by different
// components must still be read and finished whole by each reader (e.g. config/nav/tuning.yaml, nav_components.cpp).
#include <cstdint>
#include <filesystem>
#include <limits>
#include <memory>
#include <optional>
#include <set>
#include <stdexcept>
#include <string>
#include <string_view>
#include <vector>

#include <Eigen/Core>
#include <yaml-cpp/yaml.h>

namespace gdnav::core::config {

// The message is always one line: control characters (a newline in a quoted value or key, raw bytes of a garbage
// file quoted by the YAML parser) are written as \n, \r, \t or \xNN.
class ConfigError : public std::runtime_error {
public:
    explicit ConfigError(const std::string& what);
    explicit ConfigError(const char* what) : ConfigError(std::string(what)) {}
};

struct Range {
    double lo{-std::numeric_limits<double>::infinity()};
    double hi{std::numeric_limits<double>::infinity()};
    static Range nonneg() { return {0.0, std::numeric_limits<double>::infinity()}; }
    static Range positive() { return {std::numeric_limits<double>::min(), std::numeric_limits<double>::infinity()}; }
    [[nodiscard]] bool contains(double v) const { return v >= lo && v <= hi; }
    [[nodiscard]] std::string str() const;
};

class Config {
public:
    Config() = default;
    // Loads a YAML file; throws ConfigError naming the file when it is missing or malformed.
    static Config load(const std::filesystem::path& file);
    // Parses YAML text (`origin` names it in messages).
    static Config parse(const std::string& text, const std::string& origin);
    // Wraps an existing node (e.g. a section embedded in another document).
    static Config wrap(const YAML::Node& node, const std::string& origin, const std::string& path = "");

    [[nodiscard]] bool has(std::string_view key) const;
    [[nodiscard]] Config child(std::string_view key) const;  // required mapping
    [[nodiscard]] std::optional<Config> optional_child(std::string_view key) const;
    [[nodiscard]] std::vector<Config> items(std::string_view key) const;  // required sequence of mappings
    [[nodiscard]] std::vector<std::string> keys() const;                 // keys of this mapping, marks them read

    double get_double(std::string_view key, Range r = {}) const;
    double get_double(std::string_view key, double fallback, Range r) const;
    // Angle given in degrees in the file (key ends in _deg), returned in radians.
    double get_angle_deg(std::string_view key, Range deg_range = {}) const;
    std::int64_t get_int(std::string_view key, std::int64_t lo, std::int64_t hi) const;
    std::int64_t get_int(std::string_view key, std::int64_t fallback, std::int64_t lo, std::int64_t hi) const;
    std::uint64_t get_uint64(std::string_view key) const;
    bool get_bool(std::string_view key) const;
    bool get_bool(std::string_view key, bool fallback) const;
    std::string get_string(std::string_view key) const;
    std::string get_string(std::string_view key, const std::string& fallback) const;
    std::string get_choice(std::string_view key, const std::vector<std::string>& allowed) const;
    std::string get_choice(std::string_view key, const std::string& fallback,
                           const std::vector<std::string>& allowed) const;
    std::vector<double> get_doubles(std::string_view key, std::size_t min_size, std::size_t max_size,
                                    Range r = {}) const;
    Eigen::Vector3d get_vec3(std::string_view key, Range r = {}) const;
    Eigen::Matrix3d get_mat3(std::string_view key, Range r = {}) const;  // 3 rows of 3
    std::vector<std::string> get_strings(std::string_view key) const;
    // A file named relative to `dir` (e.g. `aircraft: aircraft/mugin.yaml` relative to config/): returns dir / value
    // and fails naming this key when it is not an existing regular file.
    std::filesystem::path get_file(std::string_view key, const std::filesystem::path& dir) const;
    std::filesystem::path get_file(std::string_view key, const std::string& fallback,
                                   const std::filesystem::path& dir) const;

    // Throws for any key below this node that no getter read (recursively for mappings that were read).
    void finish() const;

    [[nodiscard]] const std::string& origin() const { return state_->origin; }
    [[nodiscard]] std::string key_path(std::string_view key) const;
    [[nodiscard]] const YAML::Node& node() const { return node_; }
    [[noreturn]] void fail(std::string_view key, const std::string& what) const;

private:
    struct State {
        std::string origin;
        std::set<std::string> read;
    };
    Config(YAML::Node node, std::shared_ptr<State> state, std::string path);
    YAML::Node require(std::string_view key) const;
    void mark(std::string_view key) const;
    void check_unread(const YAML::Node& node, const std::string& path) const;

    YAML::Node node_;
    std::shared_ptr<State> state_;
    std::string path_;
};

}  // namespace gdnav::core::config
namespace gdnav { namespace config = core::config; }  // the short name (docs/architecture.md, "Namespaces")
