// The process members of a run (launch/member_process): placeholders, environment, the executable found on PATH or
// relative to the working directory, the file hashed (an interpreter's script, else the executable), and the
// refusals before anything starts. No process is started.
#include "launch/member_process.hpp"

#include <gtest/gtest.h>
#include <sys/stat.h>

#include <fstream>

#include "temp_dir.hpp"

namespace gdnav::launch {
namespace {

namespace fs = std::filesystem;

framework::RunConfig config_with(const std::string& members, int domain = 164) {
    framework::RunConfig rc =
        framework::RunConfig::parse("run: {seed: 1, steps: 10, run_index: 4, out_dir: /tmp/o, members: " + members +
                                        "}\ncomponents: {nav: {type: y}}\n",
                                    "t.yaml");
    rc.domain_id = domain;  // as the launcher's choose_domain sets it
    return rc;
}

std::string error_of(const framework::RunConfig& rc) {
    try {
        (void)resolve_member_processes(rc);
    } catch (const config::ConfigError& e) {
        return e.what();
    }
    return "";
}

TEST(Sha256, KnownDigestOfAbc) {
    gdnav::test::TempDir dir;
    std::ofstream(dir.path() / "abc") << "abc";
    // FIPS 180-2, appendix B.1.
    EXPECT_EQ(sha256_of_file(dir.path() / "abc"), "ba7816bf8f01cfea414140de5dae2223b00361a396177a9cb410ff61f20015ad");
    EXPECT_THROW((void)sha256_of_file(dir.path() / "missing"), std::runtime_error);
}

TEST(MemberProcess, PlaceholdersEnvironmentAndTheExecutableOnPath) {
    const framework::RunConfig rc = config_with("{nav: {command: [sh, -c, 'echo {domain} {run} {out}', '{security}'], "
                                     "env: {MY: 'r{run}'}}}");
    const auto ps = resolve_member_processes(rc);
    ASSERT_EQ(ps.size(), 1u);
    const MemberProcess& m = ps[0];
    EXPECT_EQ(m.argv, (std::vector<std::string>{"sh", "-c", "echo 164 4 /tmp/o", ""}));
    EXPECT_TRUE(m.exe.is_absolute());
    EXPECT_EQ(m.exe.filename(), "sh");
    EXPECT_EQ(m.file, m.exe);  // `sh -c CODE` runs no script file: the interpreter is hashed
    EXPECT_EQ(m.sha256, sha256_of_file(m.exe));
    EXPECT_EQ(m.cwd, fs::current_path());
    auto value = [&m](const std::string& k) {
        for (const auto& [key, v] : m.env)
            if (key == k) return v;
        return std::string("<unset>");
    };
    EXPECT_EQ(value("MY"), "r4");
    EXPECT_EQ(value("GDNAV_MEMBER"), "nav");
    EXPECT_EQ(value("GDNAV_DOMAIN"), "164");
    EXPECT_EQ(value("GDNAV_RUN"), "4");
    EXPECT_EQ(value("GDNAV_OUT"), "/tmp/o");
    EXPECT_EQ(value("GDNAV_SECURITY"), "");
}

TEST(MemberProcess, AnInterpretersScriptIsTheFileHashedAndRecorded) {
    gdnav::test::TempDir dir;
    std::ofstream(dir.path() / "f.py") << "print('member')\n";
    const framework::RunConfig rc =
        config_with("{nav: {command: [python3, -u, f.py, --x-k, '1'], cwd: '" + dir.path().string() + "'}}");
    const auto ps = resolve_member_processes(rc);
    ASSERT_EQ(ps.size(), 1u);
    EXPECT_EQ(ps[0].file, dir.path() / "f.py");
    EXPECT_EQ(ps[0].sha256, sha256_of_file(dir.path() / "f.py"));
    const std::string rec = member_process_record(ps[0], 42);
    EXPECT_EQ(rec.rfind("nav: {pid: 42, command: [python3, -u, f.py, --x-k, 1]", 0), 0u) << rec;
    EXPECT_NE(rec.find("sha256: " + ps[0].sha256), std::string::npos) << rec;
}

TEST(MemberProcess, AnExecutableRelativeToTheWorkingDirectory) {
    gdnav::test::TempDir dir;
    std::ofstream(dir.path() / "run.sh") << "#!/bin/sh\nexit 0\n";
    std::ofstream(dir.path() / "plain.txt") << "x";
    chmod((dir.path() / "run.sh").c_str(), 0755);
    const std::string cwd = "cwd: '" + dir.path().string() + "'";
    const auto ps = resolve_member_processes(config_with("{nav: {command: [./run.sh], " + cwd + "}}"));
    ASSERT_EQ(ps.size(), 1u);
    EXPECT_EQ(ps[0].exe, dir.path() / "run.sh");
    EXPECT_EQ(ps[0].file, ps[0].exe);
    EXPECT_NE(error_of(config_with("{nav: {command: [./plain.txt], " + cwd + "}}")).find("run.members.nav.command"),
              std::string::npos);
}

TEST(MemberProcess, MissingCommandOrDirectoryIsOneLineNamingTheKey) {
    const std::string e1 = error_of(config_with("{nav: {command: [gdnav-no-such-program-x]}}"));
    EXPECT_NE(e1.find("key 'run.members.nav.command': 'gdnav-no-such-program-x' is not an executable file on PATH"),
              std::string::npos)
        << e1;
    const std::string e2 = error_of(config_with("{nav: {command: [sh], cwd: /no/such/dir}}"));
    EXPECT_NE(e2.find("key 'run.members.nav.cwd'"), std::string::npos) << e2;
    EXPECT_EQ(e1.find('\n'), std::string::npos);
}

TEST(MemberProcess, DirectLayoutAndInProcessPythonAreRefused) {
    const framework::RunConfig rc = config_with("{nav: {command: [sh]}}");
    EXPECT_NO_THROW(check_started_members(rc, "composed"));
    EXPECT_NO_THROW(check_started_members(rc, "distributed"));
    try {
        check_started_members(rc, "direct");
        FAIL() << "direct accepted a process member";
    } catch (const config::ConfigError& e) {
        EXPECT_NE(std::string(e.what()).find("run.members.nav': a process member needs the lockstep clock"),
                  std::string::npos)
            << e.what();
    }
    // An in-process Python member is a component of the run (framework/run_members.hpp), not a process.
    const framework::RunConfig py = config_with("{nav: {python: {file: f.py, class: C}}}");
    EXPECT_NO_THROW(check_started_members(py, "direct"));
    EXPECT_TRUE(framework::started_members(py).empty());
    EXPECT_TRUE(resolve_member_processes(py).empty());
}

}  // namespace
}  // namespace gdnav::launch
