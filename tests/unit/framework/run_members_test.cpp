// run.members and --member NAME=SPEC: the command-line splitting, the entries they stand for, and the entries a run
// configuration accepts or refuses (each refusal one line naming the key).
#include <gtest/gtest.h>

#include <string>

#include "framework/run_config.hpp"
#include "framework/run_members.hpp"

using namespace gdnav;
using namespace gdnav::framework;

namespace {

const char* kRun = "run: {seed: 1, steps: 10, external: [ext]}\ncomponents: {nav: {type: y}, other: {type: y}}\n";

std::string error_of(const std::string& text) {
    try {
        (void)RunConfig::parse(text, "t.yaml");
    } catch (const config::ConfigError& e) {
        return e.what();
    }
    return "";
}

}  // namespace

TEST(SplitCommandLine, QuotesAndBackslashesAsAShellWouldWithoutExpanding) {
    using V = std::vector<std::string>;
    EXPECT_EQ(split_command_line("  python3  my.py --x-gain 0.5 ", "t"), (V{"python3", "my.py", "--x-gain", "0.5"}));
    EXPECT_EQ(split_command_line("a 'b c' \"d \\\"e\\\" $HOME\" f\\ g ''", "t"),
              (V{"a", "b c", "d \"e\" $HOME", "f g", ""}));
    EXPECT_EQ(split_command_line("x --domain {domain} --out={out}/m", "t"),
              (V{"x", "--domain", "{domain}", "--out={out}/m"}));
    EXPECT_EQ(split_command_line("a\"b\"'c'", "t"), (V{"abc"}));
    EXPECT_THROW((void)split_command_line("a 'b", "t"), config::ConfigError);
    EXPECT_THROW((void)split_command_line("a \"b", "t"), config::ConfigError);
    EXPECT_THROW((void)split_command_line("a \\", "t"), config::ConfigError);
}

TEST(MemberOption, CommandAndPythonFormsAndMalformedSpecs) {
    auto [name, node] = member_option_node("nav=python3 'my filter.py' --x-k 1");
    EXPECT_EQ(name, "nav");
    ASSERT_TRUE(node["command"].IsSequence());
    EXPECT_EQ(node["command"].size(), 4u);
    EXPECT_EQ(node["command"][1].as<std::string>(), "my filter.py");
    auto [pname, pnode] = member_option_node("nav=python:dir/f.py:MyFilter");
    EXPECT_EQ(pname, "nav");
    EXPECT_EQ(pnode["python"]["file"].as<std::string>(), "dir/f.py");
    EXPECT_EQ(pnode["python"]["class"].as<std::string>(), "MyFilter");
    for (const char* bad : {"nav", "=x", "nav=", "nav=   ", "nav=python:f.py", "nav=python::C", "nav=python:f.py:"})
        EXPECT_THROW((void)member_option_node(bad), config::ConfigError) << bad;
}

TEST(RunMembers, ACommandMemberIsExternalForTheClockAndKeepsItsSettings) {
    YAML::Node doc = YAML::Load(kRun);
    add_member_options(doc, {"nav=./f --domain {domain}", "extra=python3 x.py"});
    YAML::Emitter em;
    em << doc;
    const RunConfig rc = RunConfig::parse(em.c_str(), "t.yaml");
    const auto started = started_members(rc);
    ASSERT_EQ(started.size(), 2u);
    EXPECT_TRUE(rc.is_external("nav"));    // replaces the configured component
    EXPECT_TRUE(rc.is_external("extra"));  // a new member, as in run.external
    EXPECT_EQ(rc.member_names(), (std::vector<std::string>{"nav", "other", "ext", "extra"}));
    ASSERT_NE(find_started(started, "nav"), nullptr);
    EXPECT_EQ(find_started(started, "nav")->command.back(), "{domain}");
    EXPECT_EQ(find_started(started, "other"), nullptr);
    // The resolved document keeps run.members: every process of the run reads the same.
    const RunConfig again = RunConfig::parse(rc.to_yaml(), "again");
    EXPECT_EQ(started_members(again).size(), 2u);
    EXPECT_TRUE(again.is_external("extra"));
}

TEST(RunMembers, FileFormWithCwdEnvAndThePythonFormBecomesAComponent) {
    const RunConfig rc = RunConfig::parse(
        "run: {seed: 1, steps: 10, members: {nav: {command: [a, b], cwd: w, env: {K: v, N: 3}}, "
        "py: {python: {file: f.py, class: C}}}}\ncomponents: {nav: {type: y}}\n", "t.yaml");
    const auto started = started_members(rc);
    ASSERT_EQ(started.size(), 1u);  // the python entry is a component of the run, not a process
    EXPECT_EQ(started[0].cwd, "w");
    EXPECT_EQ(started[0].env.size(), 2u);
    EXPECT_EQ(started[0].env[1], (std::pair<std::string, std::string>{"N", "3"}));
    EXPECT_FALSE(rc.is_external("py"));  // hosted by gdnav
    const YAML::Node doc = YAML::Load(rc.to_yaml());
    EXPECT_EQ(doc["components"]["py"]["type"].as<std::string>(), kPythonMemberType);
    EXPECT_EQ(doc["components"]["py"]["class"].as<std::string>(), "C");
    EXPECT_FALSE(doc["run"]["members"]["py"]);
}

TEST(RunMembers, RefusalsNameTheKey) {
    auto with = [](const std::string& members) {
        return error_of("run: {seed: 1, steps: 10, external: [ext], members: " + members +
                        "}\ncomponents: {nav: {type: y}}\n");
    };
    EXPECT_NE(with("{ext: {command: [a]}}").find("run.members.ext"), std::string::npos);  // in run.external too
    EXPECT_NE(with("{clock: {command: [a]}}").find("run.members.clock"), std::string::npos);
    EXPECT_NE(with("{nav: {command: []}}").find("run.members.nav.command"), std::string::npos);
    EXPECT_NE(with("{nav: {command: [a], python: {file: f, class: c}}}").find("either command or python"),
              std::string::npos);
    EXPECT_NE(with("{nav: {}}").find("either command or python"), std::string::npos);
    EXPECT_NE(with("{nav: {command: [a], shell: true}}").find("run.members.nav.shell"), std::string::npos);
    EXPECT_NE(with("{nav: {command: [a], env: {GDNAV_DOMAIN: 3}}}").find("run.members.nav.env.GDNAV_DOMAIN"),
              std::string::npos);
    EXPECT_NE(with("{'a b': {command: [a]}}").find("not a member name"), std::string::npos);
}
