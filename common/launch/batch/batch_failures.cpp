#include "launch/batch/batch_failures.hpp"

#include <algorithm>
#include <fstream>
#include <regex>
#include <sstream>

#include <yaml-cpp/yaml.h>

#include "launch/batch/batch_dir.hpp"

namespace gdnav::launch::batch {

namespace fs = std::filesystem;

namespace {

void emit_lines(YAML::Emitter& em, const std::vector<std::string>& lines) {
    em << YAML::BeginSeq;
    for (const auto& l : lines) em << YAML::DoubleQuoted << l;
    em << YAML::EndSeq;
}

void emit_failure(YAML::Emitter& em, const RunFailure& f) {
    em << YAML::BeginMap;
    em << YAML::Key << "run" << YAML::Value << f.run;
    em << YAML::Key << "dir" << YAML::Value << ("runs/" + run_dir_name(f.run));
    em << YAML::Key << "exit_code" << YAML::Value << f.exit_code;
    em << YAML::Key << "cause" << YAML::Value << YAML::DoubleQuoted << f.cause;
    em << YAML::Key << "log_tail" << YAML::Value;
    emit_lines(em, f.log_tail);
    em << YAML::Key << "member_logs" << YAML::Value << YAML::BeginMap;
    for (const auto& [name, lines] : f.member_tails) {
        em << YAML::Key << name << YAML::Value;
        emit_lines(em, lines);
    }
    em << YAML::EndMap << YAML::EndMap;
}

std::vector<std::string> strings_of(const YAML::Node& n) {
    std::vector<std::string> v;
    if (n && n.IsSequence())
        for (const auto& x : n) v.push_back(x.as<std::string>());
    return v;
}

RunFailure parse_failure(const YAML::Node& n) {
    RunFailure f;
    f.run = n["run"].as<std::uint64_t>();
    f.exit_code = n["exit_code"].as<int>();
    f.cause = n["cause"] ? n["cause"].as<std::string>() : "";
    f.log_tail = strings_of(n["log_tail"]);
    if (n["member_logs"] && n["member_logs"].IsMap())
        for (const auto& kv : n["member_logs"])
            f.member_tails.emplace_back(kv.first.as<std::string>(), strings_of(kv.second));
    return f;
}

}  // namespace

std::vector<std::string> last_lines(const fs::path& file, std::size_t n) {
    std::ifstream in(file, std::ios::binary);
    if (!in) return {};
    in.seekg(0, std::ios::end);
    const auto size = static_cast<std::streamoff>(in.tellg());
    const std::streamoff from = std::max<std::streamoff>(0, size - 16384);
    in.seekg(from);
    std::string line;
    std::vector<std::string> lines;
    if (from > 0) std::getline(in, line);  // a partial first line
    while (std::getline(in, line)) {
        while (!line.empty() && (line.back() == '\r' || line.back() == ' ')) line.pop_back();
        if (!line.empty()) lines.push_back(line);
    }
    if (lines.size() > n) lines.erase(lines.begin(), lines.end() - static_cast<std::ptrdiff_t>(n));
    return lines;
}

RunFailure record_run_failure(const fs::path& run_dir, std::uint64_t run, int exit_code) {
    RunFailure f;
    f.run = run;
    f.exit_code = exit_code;
    f.log_tail = last_lines(run_dir / "log.txt", kFailureTailLines);
    f.cause = f.log_tail.empty() ? "(no output in log.txt)" : f.log_tail.back();
    std::error_code ec;
    std::vector<fs::path> logs;
    for (const auto& e : fs::directory_iterator(run_dir / "logs", ec))
        if (e.path().extension() == ".log") logs.push_back(e.path());
    std::sort(logs.begin(), logs.end());
    for (const auto& l : logs) f.member_tails.emplace_back(l.stem().string(), last_lines(l, kFailureTailLines));
    if (fs::exists(run_dir / "metrics.yaml", ec))
        fs::rename(run_dir / "metrics.yaml", run_dir / "metrics.failed.yaml", ec);
    YAML::Emitter em;
    emit_failure(em, f);
    write_file_atomic(run_dir / "failure.yaml",
                      std::string("# This run failed (gdnav montecarlo); running the batch again reruns it\n") +
                          em.c_str() + "\n");
    return f;
}

std::vector<RunFailure> read_run_failures(const fs::path& batch_dir) {
    static const std::regex run_name(R"(run_\d{4,})");
    std::vector<RunFailure> out;
    std::error_code ec;
    for (const auto& e : fs::directory_iterator(batch_dir / "runs", ec)) {
        const fs::path file = e.path() / "failure.yaml";
        if (!std::regex_match(e.path().filename().string(), run_name) || !fs::exists(file, ec)) continue;
        try {
            out.push_back(parse_failure(YAML::LoadFile(file.string())));
        } catch (const std::exception&) {
        }
    }
    std::sort(out.begin(), out.end(), [](const RunFailure& a, const RunFailure& b) { return a.run < b.run; });
    return out;
}

void write_failures_summary(const fs::path& batch_dir) {
    const std::vector<RunFailure> failures = read_run_failures(batch_dir);
    const fs::path file = batch_dir / "failures.yaml";
    std::error_code ec;
    if (failures.empty()) {
        fs::remove(file, ec);
        return;
    }
    YAML::Emitter em;
    em << YAML::BeginMap << YAML::Key << "failed" << YAML::Value << YAML::BeginSeq;
    for (const auto& f : failures) emit_failure(em, f);
    em << YAML::EndSeq << YAML::EndMap;
    write_file_atomic(file, "# Failed runs of this batch (gdnav montecarlo; the same command again reruns them)\n" +
                                std::string(em.c_str()) + "\n");
}

std::string failures_markdown(const std::vector<RunFailure>& failures, const std::string& where) {
    if (failures.empty()) return "";
    std::ostringstream md;
    md << "\n## Failed runs (" << where << ")\n\n"
       << "Run the same `gdnav montecarlo` command again to rerun them (docs/montecarlo.md, \"Failed runs\").\n";
    for (const auto& f : failures) {
        md << "\n### run " << f.run << ": exit code " << f.exit_code << "\n\n`" << f.cause << "`\n\n```\n";
        for (const auto& l : f.log_tail) md << l << "\n";
        md << "```\n";
        for (const auto& [name, lines] : f.member_tails) {
            md << "\n" << name << " (logs/" << name << ".log):\n\n```\n";
            for (const auto& l : lines) md << l << "\n";
            md << "```\n";
        }
    }
    return md.str();
}

}  // namespace gdnav::launch::batch
