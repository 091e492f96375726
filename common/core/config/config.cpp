#include "config/config.hpp"

#include <cmath>
#include <fstream>
#include <sstream>

namespace gdnav::core::config {

namespace {
std::string one_line(const std::string& s) {
    std::string out;
    out.reserve(s.size());
    for (const char c : s) {
        const auto u = static_cast<unsigned char>(c);
        if (u >= 0x20 && u != 0x7f) {
            out.push_back(c);
        } else if (c == '\n') {
            out += "\\n";
        } else if (c == '\r') {
            out += "\\r";
        } else if (c == '\t') {
            out += "\\t";
        } else {
            static const char* hex = "0123456789abcdef";
            out += "\\x";
            out.push_back(hex[u >> 4]);
            out.push_back(hex[u & 15]);
        }
    }
    return out;
}

std::string fmt_num(double v) {
    if (std::isinf(v)) return v > 0 ? "inf" : "-inf";
    std::ostringstream os;
    os << v;
    return os.str();
}
std::string join(const std::vector<std::string>& v) {
    std::string s;
    for (const auto& x : v) s += (s.empty() ? "" : ", ") + x;
    return s;
}
// Every mapping key is a plain scalar and appears once (yaml-cpp keeps duplicates and returns the first on lookup,
// so a repeated key would silently ignore the second value).
void check_keys(const YAML::Node& node, const std::string& path, const std::string& origin) {
    if (node.IsMap()) {
        std::set<std::string> seen;
        for (const auto& kv : node) {
            if (!kv.first.IsScalar())
                throw ConfigError("config error: " + origin + ": key '" + path +
                                  "': has a key that is not a plain name");
            const std::string k = kv.first.Scalar();
            const std::string p = path.empty() ? k : path + "." + k;
            if (!seen.insert(k).second)
                throw ConfigError("config error: " + origin + ": key '" + p + "': duplicate key");
            check_keys(kv.second, p, origin);
        }
    } else if (node.IsSequence()) {
        for (std::size_t i = 0; i < node.size(); ++i) check_keys(node[i], path + "[" + std::to_string(i) + "]", origin);
    }
}
}  // namespace

ConfigError::ConfigError(const std::string& what) : std::runtime_error(one_line(what)) {}

std::string Range::str() const {
    return (std::isinf(lo) ? std::string("(") : std::string("[")) + fmt_num(lo) + ", " + fmt_num(hi) +
           (std::isinf(hi) ? ")" : "]");
}

Config::Config(YAML::Node node, std::shared_ptr<State> state, std::string path)
    : node_(std::move(node)), state_(std::move(state)), path_(std::move(path)) {}

Config Config::load(const std::filesystem::path& file) {
    std::ifstream in(file);
    if (!in) throw ConfigError("config error: " + file.string() + ": cannot open file");
    std::stringstream ss;
    ss << in.rdbuf();
    return parse(ss.str(), file.string());
}

Config Config::parse(const std::string& text, const std::string& origin) {
    YAML::Node n;
    try {
        n = YAML::Load(text);
    } catch (const YAML::Exception& e) {
        throw ConfigError("config error: " + origin + ": malformed YAML at line " + std::to_string(e.mark.line + 1) +
                          ": " + e.msg);
    }
    if (!n.IsMap()) throw ConfigError("config error: " + origin + ": top level must be a mapping of keys");
    check_keys(n, "", origin);
    auto st = std::make_shared<State>();
    st->origin = origin;
    return Config(n, st, "");
}

Config Config::wrap(const YAML::Node& node, const std::string& origin, const std::string& path) {
    auto st = std::make_shared<State>();
    st->origin = origin;
    if (!node.IsMap()) throw ConfigError("config error: " + origin + ": key '" + path + "' must be a mapping");
    return Config(node, st, path);
}

std::string Config::key_path(std::string_view key) const {
    return path_.empty() ? std::string(key) : path_ + "." + std::string(key);
}

void Config::fail(std::string_view key, const std::string& what) const {
    throw ConfigError("config error: " + state_->origin + ": key '" + key_path(key) + "': " + what);
}

bool Config::has(std::string_view key) const { return node_.IsMap() && node_[std::string(key)].IsDefined(); }

void Config::mark(std::string_view key) const { state_->read.insert(key_path(key)); }

YAML::Node Config::require(std::string_view key) const {
    if (!has(key)) fail(key, "missing (required)");
    mark(key);
    return node_[std::string(key)];
}

Config Config::child(std::string_view key) const {
    YAML::Node n = require(key);
    if (!n.IsMap()) fail(key, "must be a mapping");
    return Config(n, state_, key_path(key));
}

std::optional<Config> Config::optional_child(std::string_view key) const {
    if (!has(key)) return std::nullopt;
    return child(key);
}

std::vector<Config> Config::items(std::string_view key) const {
    YAML::Node n = require(key);
    if (!n.IsSequence()) fail(key, "must be a list");
    std::vector<Config> out;
    for (std::size_t i = 0; i < n.size(); ++i) {
        const std::string p = key_path(key) + "[" + std::to_string(i) + "]";
        if (!n[i].IsMap()) throw ConfigError("config error: " + state_->origin + ": key '" + p + "': must be a mapping");
        state_->read.insert(p);
        out.push_back(Config(n[i], state_, p));
    }
    return out;
}

std::vector<std::string> Config::keys() const {
    std::vector<std::string> out;
    for (const auto& kv : node_) {
        out.push_back(kv.first.as<std::string>());
    }
    return out;
}

double Config::get_double(std::string_view key, Range r) const {
    YAML::Node n = require(key);
    double v = 0.0;
    try {
        if (!n.IsScalar()) throw YAML::Exception(YAML::Mark::null_mark(), "not a scalar");
        v = n.as<double>();
    } catch (const YAML::Exception&) {
        fail(key, "must be a number in " + r.str());
    }
    if (!std::isfinite(v) || !r.contains(v)) fail(key, "value " + fmt_num(v) + " outside allowed range " + r.str());
    return v;
}

double Config::get_double(std::string_view key, double fallback, Range r) const {
    return has(key) ? get_double(key, r) : fallback;
}

double Config::get_angle_deg(std::string_view key, Range deg_range) const {
    return get_double(key, deg_range) * 3.14159265358979323846 / 180.0;
}

std::int64_t Config::get_int(std::string_view key, std::int64_t lo, std::int64_t hi) const {
    YAML::Node n = require(key);
    std::int64_t v = 0;
    try {
        if (!n.IsScalar()) throw YAML::Exception(YAML::Mark::null_mark(), "not a scalar");
        v = n.as<std::int64_t>();
    } catch (const YAML::Exception&) {
        fail(key, "must be an integer in [" + std::to_string(lo) + ", " + std::to_string(hi) + "]");
    }
    if (v < lo || v > hi)
        fail(key, "value " + std::to_string(v) + " outside allowed range [" + std::to_string(lo) + ", " +
                      std::to_string(hi) + "]");
    return v;
}

std::int64_t Config::get_int(std::string_view key, std::int64_t fallback, std::int64_t lo, std::int64_t hi) const {
    return has(key) ? get_int(key, lo, hi) : fallback;
}

std::uint64_t Config::get_uint64(std::string_view key) const {
    YAML::Node n = require(key);
    try {
        if (!n.IsScalar() || n.Scalar().empty() || n.Scalar()[0] == '-') throw YAML::Exception({}, "");
        return n.as<std::uint64_t>();
    } catch (const YAML::Exception&) {
        fail(key, "must be a non-negative integer");
    }
}

bool Config::get_bool(std::string_view key) const {
    YAML::Node n = require(key);
    try {
        if (!n.IsScalar()) throw YAML::Exception({}, "");
        return n.as<bool>();
    } catch (const YAML::Exception&) {
        fail(key, "must be true or false");
    }
}

bool Config::get_bool(std::string_view key, bool fallback) const { return has(key) ? get_bool(key) : fallback; }

std::string Config::get_string(std::string_view key) const {
    YAML::Node n = require(key);
    if (!n.IsScalar()) fail(key, "must be a string");
    return n.as<std::string>();
}

std::string Config::get_string(std::string_view key, const std::string& fallback) const {
    return has(key) ? get_string(key) : fallback;
}

std::string Config::get_choice(std::string_view key, const std::vector<std::string>& allowed) const {
    const std::string v = get_string(key);
    for (const auto& a : allowed)
        if (a == v) return v;
    fail(key, "value '" + v + "' not one of {" + join(allowed) + "}");
}

std::string Config::get_choice(std::string_view key, const std::string& fallback,
                               const std::vector<std::string>& allowed) const {
    return has(key) ? get_choice(key, allowed) : fallback;
}

std::vector<double> Config::get_doubles(std::string_view key, std::size_t min_size, std::size_t max_size,
                                        Range r) const {
    YAML::Node n = require(key);
    if (!n.IsSequence() || n.size() < min_size || n.size() > max_size)
        fail(key, "must be a list of " +
                      (min_size == max_size ? std::to_string(min_size)
                                            : std::to_string(min_size) + " to " + std::to_string(max_size)) +
                      " numbers in " + r.str());
    std::vector<double> out;
    for (std::size_t i = 0; i < n.size(); ++i) {
        double v = 0.0;
        try {
            v = n[i].as<double>();
        } catch (const YAML::Exception&) {
            fail(key, "element " + std::to_string(i) + " must be a number in " + r.str());
        }
        if (!std::isfinite(v) || !r.contains(v))
            fail(key, "element " + std::to_string(i) + " value " + fmt_num(v) + " outside allowed range " + r.str());
        out.push_back(v);
    }
    return out;
}

Eigen::Vector3d Config::get_vec3(std::string_view key, Range r) const {
    const auto v = get_doubles(key, 3, 3, r);
    return {v[0], v[1], v[2]};
}

Eigen::Matrix3d Config::get_mat3(std::string_view key, Range r) const {
    const auto v = get_doubles(key, 9, 9, r);
    Eigen::Matrix3d m;
    m << v[0], v[1], v[2], v[3], v[4], v[5], v[6], v[7], v[8];
    return m;
}

std::vector<std::string> Config::get_strings(std::string_view key) const {
    YAML::Node n = require(key);
    if (!n.IsSequence()) fail(key, "must be a list of strings");
    std::vector<std::string> out;
    for (std::size_t i = 0; i < n.size(); ++i) {
        if (!n[i].IsScalar()) fail(key, "element " + std::to_string(i) + " must be a string");
        out.push_back(n[i].as<std::string>());
    }
    return out;
}

std::filesystem::path Config::get_file(std::string_view key, const std::filesystem::path& dir) const {
    const std::string v = get_string(key);
    const std::filesystem::path p = dir / v;
    std::error_code ec;
    if (v.empty() || !std::filesystem::is_regular_file(p, ec)) fail(key, "no such file '" + p.string() + "'");
    return p;
}

std::filesystem::path Config::get_file(std::string_view key, const std::string& fallback,
                                       const std::filesystem::path& dir) const {
    return has(key) ? get_file(key, dir) : dir / fallback;
}

void Config::check_unread(const YAML::Node& node, const std::string& path) const {
    if (node.IsMap()) {
        for (const auto& kv : node) {
            const std::string k = kv.first.as<std::string>();
            const std::string p = path.empty() ? k : path + "." + k;
            if (!state_->read.count(p))
                throw ConfigError("config error: " + state_->origin + ": key '" + p + "': unknown key");
            check_unread(kv.second, p);
        }
    } else if (node.IsSequence()) {
        for (std::size_t i = 0; i < node.size(); ++i) {
            const std::string p = path + "[" + std::to_string(i) + "]";
            if (node[i].IsMap() && state_->read.count(p)) check_unread(node[i], p);
        }
    }
}

void Config::finish() const { check_unread(node_, path_); }

}  // namespace gdnav::core::config
