#include "framework/run_members.hpp"

#include <algorithm>
#include <filesystem>

#include "framework/lockstep.hpp"
#include "framework/run_config.hpp"

namespace gdnav::framework {

using config::Config;
using config::ConfigError;

namespace {

// One `python:` entry -> the component section that replaces (or adds) member `name`.
YAML::Node python_component(const Config& entry, const YAML::Node& replaced) {
    const Config py = entry.child("python");
    const std::string file = py.get_string("file");
    const std::string cls = py.get_string("class");
    py.finish();
    entry.finish();
    if (file.empty()) py.fail("file", "empty (the Python file that defines the member's class)");
    if (cls.empty()) py.fail("class", "empty (the name of the member's class in the file)");
    YAML::Node c(YAML::NodeType::Map);
    c["type"] = kPythonMemberType;
    // Absolute, so that every process of the run (started in the same working directory) and run.yaml name it.
    c["file"] = std::filesystem::absolute(file).lexically_normal().string();
    c["class"] = cls;
    if (replaced && replaced.IsMap() && replaced["type"] && replaced["type"].IsScalar())
        c["replaces"] = replaced["type"].as<std::string>();
    return c;
}

}  // namespace

void apply_inprocess_members(YAML::Node& root, const std::string& origin) {
    YAML::Node run = root["run"];
    if (!run || !run.IsMap() || !run["members"]) return;
    const Config top = Config::wrap(root, origin);
    const Config members = top.child("run").child("members");
    std::vector<std::string> external;
    if (run["external"] && run["external"].IsSequence())
        for (const auto& e : run["external"]) external.push_back(e.as<std::string>());
    std::vector<std::string> hosted;
    for (const auto& name : members.keys()) {
        const Config entry = members.child(name);
        // A member of another kind, or one giving both kinds (read_started_members refuses it).
        if (!entry.has("python") || entry.has("command")) continue;
        if (name.empty() || name.size() > 63 || name.find_first_of(", \t") != std::string::npos)
            members.fail(name, "not a member name (1-63 characters, no commas or spaces)");
        if (name == kClockName) members.fail(name, "'clock' is the lockstep clock and cannot be replaced");
        if (std::find(external.begin(), external.end(), name) != external.end())
            members.fail(name, "also listed in run.external: a member is either hosted here or external");
        YAML::Node comps = root["components"];
        if (!comps || !comps.IsMap()) top.fail("components", "missing (required)");
        comps[name] = python_component(entry, comps[name]);
        hosted.push_back(name);
    }
    for (const auto& name : hosted) run["members"].remove(name);
    if (run["members"].size() == 0) run.remove("members");
}

std::vector<std::string> split_command_line(const std::string& text, const std::string& what) {
    std::vector<std::string> words;
    std::string word;
    bool in_word = false;
    for (std::size_t i = 0; i < text.size(); ++i) {
        const char c = text[i];
        if (c == ' ' || c == '\t' || c == '\n') {
            if (in_word) words.push_back(word);
            word.clear();
            in_word = false;
            continue;
        }
        in_word = true;
        if (c == '\'') {
            const std::size_t end = text.find('\'', i + 1);
            if (end == std::string::npos) throw ConfigError("config error: " + what + ": unclosed ' in the command");
            word += text.substr(i + 1, end - i - 1);
            i = end;
        } else if (c == '"') {
            std::size_t j = i + 1;
            for (; j < text.size() && text[j] != '"'; ++j) {
                const bool escape = text[j] == '\\' && j + 1 < text.size() &&
                                    std::string("\"\\$`").find(text[j + 1]) != std::string::npos;
                if (escape) ++j;
                word += text[j];
            }
            if (j >= text.size()) throw ConfigError("config error: " + what + ": unclosed \" in the command");
            i = j;
        } else if (c == '\\') {
            if (i + 1 >= text.size()) throw ConfigError("config error: " + what + ": the command ends with a \\");
            word += text[++i];
        } else {
            word += c;
        }
    }
    if (in_word) words.push_back(word);
    return words;
}

std::pair<std::string, YAML::Node> member_option_node(const std::string& option) {
    const std::string what = "--member " + option;
    const std::size_t eq = option.find('=');
    if (eq == std::string::npos || eq == 0)
        throw ConfigError("config error: " + what + ": expected NAME=COMMAND or NAME=python:FILE.py:CLASS");
    const std::string name = option.substr(0, eq);
    const std::string spec = option.substr(eq + 1);
    YAML::Node node(YAML::NodeType::Map);
    if (spec.rfind("python:", 0) == 0) {
        const std::size_t colon = spec.rfind(':');
        const std::string file = spec.substr(7, colon > 7 ? colon - 7 : 0);
        const std::string cls = colon > 7 ? spec.substr(colon + 1) : "";
        if (file.empty() || cls.empty())
            throw ConfigError("config error: " + what + ": expected python:FILE.py:CLASS");
        node["python"]["file"] = file;
        node["python"]["class"] = cls;
        return {name, node};
    }
    const std::vector<std::string> argv = split_command_line(spec, what);
    if (argv.empty()) throw ConfigError("config error: " + what + ": the command is empty");
    node["command"] = YAML::Node(YAML::NodeType::Sequence);
    for (const auto& a : argv) node["command"].push_back(a);
    return {name, node};
}

void add_member_options(YAML::Node& root, const std::vector<std::string>& options) {
    for (const auto& option : options) {
        auto [name, node] = member_option_node(option);
        root["run"]["members"][name] = node;
    }
}

namespace {

// One process member: its argv, working directory and extra environment.
void read_command(StartedMember& m, const Config& c) {
    m.command = c.get_strings("command");
    if (m.command.empty() || m.command.front().empty()) c.fail("command", "the command is empty");
    m.cwd = c.get_string("cwd", "");
    if (const auto env = c.optional_child("env")) {
        for (const auto& k : env->keys()) {
            const auto& own = member_env_names();
            if (std::find(own.begin(), own.end(), k) != own.end())
                env->fail(k, "set by gdnav for every member (docs/external.md); not in env:");
            if (!env->node()[k].IsScalar()) env->fail(k, "expected a string value");
            m.env.emplace_back(k, env->get_string(k));
        }
    }
}

}  // namespace

std::vector<StartedMember> read_started_members(const Config& run) {
    std::vector<StartedMember> out;
    const auto members = run.optional_child("members");
    if (!members) return out;
    for (const auto& name : members->keys()) {
        if (name.empty() || name.size() > 63 || name.find_first_of(", \t") != std::string::npos)
            members->fail(name, "'" + name + "' is not a member name (1-63 characters, no commas or spaces)");
        if (name == kClockName) members->fail(name, "'clock' is the lockstep clock and cannot be a member");
        const Config c = members->child(name);
        StartedMember m;
        m.name = name;
        if (c.has("command") == c.has("python")) c.fail("", "give either command or python");
        if (c.has("command")) {
            read_command(m, c);
        } else {
            const Config py = c.child("python");
            m.python_file = py.get_string("file");
            m.python_class = py.get_string("class");
        }
        out.push_back(std::move(m));
    }
    return out;
}

std::vector<StartedMember> started_members(const RunConfig& rc) {
    const Config top = Config::parse(rc.to_yaml(), rc.origin);
    return read_started_members(top.child("run"));
}

const StartedMember* find_started(const std::vector<StartedMember>& members, const std::string& name) {
    for (const auto& m : members)
        if (m.name == name) return &m;
    return nullptr;
}

}  // namespace gdnav::framework
