#include "scenario_yaml.hpp"

#include <charconv>
#include <cmath>

#include "config/config.hpp"
#include "math/rotation.hpp"

namespace gdnav::scenario {

using config::ConfigError;

std::string shortest(double v) {
    char buf[64];
    const auto r = std::to_chars(buf, buf + sizeof(buf), v);
    return std::string(buf, r.ptr);
}

YAML::Node number(double v) { return YAML::Node(shortest(v)); }

YAML::Node degrees(double rad) {
    const double d = math::rad2deg(rad);
    const double r = std::round(d);
    return number(std::fabs(d - r) < 1e-9 ? r : d);
}

YAML::Node flow_map() {
    YAML::Node n(YAML::NodeType::Map);
    n.SetStyle(YAML::EmitterStyle::Flow);
    return n;
}

YAML::Node channel(const char* mode, const char* key, const YAML::Node& value) {
    YAML::Node n = flow_map();
    n["mode"] = mode;
    n[key] = value;
    return n;
}

YAML::Node until_elapsed(double dt_s) {
    YAML::Node n = flow_map();
    n["trigger"] = "elapsed";
    n["dt_s"] = number(dt_s);
    return n;
}

void fill_missing(YAML::Node target, const YAML::Node& drawn, const std::string& path, std::vector<std::string>* kept) {
    for (const auto& kv : drawn) {
        const std::string key = kv.first.as<std::string>();
        const std::string sub = path.empty() ? key : path + "." + key;
        const YAML::Node existing = static_cast<const YAML::Node&>(target)[key];
        if (!existing) {
            // A flow-style template section ({type: guidance}) receiving a mapping or a list turns block style,
            // so the resolved file stays readable.
            if (!kv.second.IsScalar()) target.SetStyle(YAML::EmitterStyle::Block);
            target[key] = YAML::Clone(kv.second);
        } else if (existing.IsMap() && kv.second.IsMap()) {
            fill_missing(target[key], kv.second, sub, kept);
        } else if (kept) {
            kept->push_back(sub);
        }
    }
}

namespace {

std::vector<std::string> split_path(const std::string& path, const std::string& assignment) {
    std::vector<std::string> parts;
    std::size_t start = 0;
    while (true) {
        const std::size_t dot = path.find('.', start);
        parts.push_back(path.substr(start, dot == std::string::npos ? std::string::npos : dot - start));
        if (parts.back().empty()) throw ConfigError("override '" + assignment + "': empty key in the path");
        if (dot == std::string::npos) break;
        start = dot + 1;
    }
    return parts;
}

bool is_index(const std::string& s) { return !s.empty() && s.find_first_not_of("0123456789") == std::string::npos; }

}  // namespace

void apply_set(YAML::Node& doc, const std::string& assignment) {
    const std::size_t eq = assignment.find('=');
    if (eq == std::string::npos || eq == 0)
        throw ConfigError("override '" + assignment + "': expected path=value (e.g. components.sensors_air.grade=worse)");
    const std::vector<std::string> parts = split_path(assignment.substr(0, eq), assignment);
    const std::string text = assignment.substr(eq + 1);
    YAML::Node value;
    try {
        value = YAML::Load(text.empty() ? std::string("''") : text);
    } catch (const YAML::Exception& e) {
        throw ConfigError("override '" + assignment + "': the value is not valid YAML (" + e.msg + ")");
    }
    const bool remove = value.IsNull();
    // Walk with fresh handles: yaml-cpp nodes are references, so assigning through them edits `doc` itself.
    std::vector<YAML::Node> chain{doc};
    for (std::size_t i = 0; i + 1 < parts.size(); ++i) {
        YAML::Node cur = chain.back();
        const std::string& p = parts[i];
        if (cur.IsSequence() && is_index(p)) {
            const std::size_t k = std::stoul(p);
            if (k >= cur.size()) throw ConfigError("override '" + assignment + "': index " + p + " out of range");
            chain.push_back(cur[k]);
            continue;
        }
        if (cur.IsDefined() && !cur.IsNull() && !cur.IsMap())
            throw ConfigError("override '" + assignment + "': '" + p + "' is inside a value that is not a mapping");
        const YAML::Node next = static_cast<const YAML::Node&>(cur)[p];
        if (!next) {
            if (remove) return;  // removing below a missing key: nothing to do
            cur[p] = YAML::Node(YAML::NodeType::Map);
        }
        chain.push_back(cur[p]);
    }
    YAML::Node parent = chain.back();
    const std::string& last = parts.back();
    if (parent.IsSequence() && is_index(last)) {
        const std::size_t k = std::stoul(last);
        if (k >= parent.size()) throw ConfigError("override '" + assignment + "': index " + last + " out of range");
        if (remove) throw ConfigError("override '" + assignment + "': cannot remove a sequence element");
        parent[k] = value;
        return;
    }
    if (parent.IsDefined() && !parent.IsNull() && !parent.IsMap())
        throw ConfigError("override '" + assignment + "': the parent of '" + last + "' is not a mapping");
    if (remove)
        parent.remove(last);
    else
        parent[last] = value;
}

}  // namespace gdnav::scenario
