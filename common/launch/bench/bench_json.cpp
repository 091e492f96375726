#include "launch/bench/bench_json.hpp"

#include <cmath>
#include <cstdio>
#include <ctime>
#include <fstream>
#include <sstream>
#include <thread>

#include "framework/run_config.hpp"

namespace gdnav::launch::bench {

namespace {

std::string quoted(const std::string& s) {
    std::string out = "\"";
    for (const char c : s) {
        if (c == '"' || c == '\\') {
            out += '\\';
            out += c;
        } else if (static_cast<unsigned char>(c) < 0x20) {
            char b[8];
            std::snprintf(b, sizeof(b), "\\u%04x", static_cast<unsigned>(c));
            out += b;
        } else {
            out += c;
        }
    }
    return out + "\"";
}

std::string number(double v) {
    if (!std::isfinite(v)) return "null";
    char b[32];
    std::snprintf(b, sizeof(b), "%.6g", v);
    return b;
}

std::string command_output(const std::string& cmd) {
    std::string out;
    if (FILE* p = popen(cmd.c_str(), "r")) {
        char b[256];
        while (std::fgets(b, sizeof(b), p)) out += b;
        pclose(p);
    }
    while (!out.empty() && (out.back() == '\n' || out.back() == '\r')) out.pop_back();
    return out;
}

}  // namespace

MachineInfo machine_info() {
    MachineInfo m;
    std::ifstream cpu("/proc/cpuinfo");
    std::string line;
    while (std::getline(cpu, line)) {
        if (line.rfind("processor", 0) == 0) ++m.cores;
        if (m.cpu_model.empty() && line.rfind("model name", 0) == 0 && line.find(':') != std::string::npos)
            m.cpu_model = line.substr(line.find(':') + 2);
    }
    if (m.cores == 0) m.cores = std::thread::hardware_concurrency();
    if (m.cpu_model.empty()) m.cpu_model = "unknown";
    std::ifstream("/proc/loadavg") >> m.load_1min;
    const std::string src = framework::config_dir().parent_path().string();
    m.git_commit = command_output("git -C '" + src + "' rev-parse HEAD 2>/dev/null");
    if (m.git_commit.size() != 40)
        m.git_commit = "unknown";
    else
        m.git_dirty = !command_output("git -C '" + src + "' status --porcelain --untracked-files=no 2>/dev/null").empty();
    const std::time_t now = std::time(nullptr);
    char b[32];
    std::strftime(b, sizeof(b), "%Y-%m-%dT%H:%M:%SZ", std::gmtime(&now));
    m.date_utc = b;
    return m;
}

std::string bench_json(const BenchFigures& f, const MachineInfo& m) {
    std::ostringstream o;
    o << "{\n  \"format\": \"gdnav-bench\",\n  \"format_version\": 1,\n  \"date_utc\": " << quoted(m.date_utc)
      << ",\n  \"git_commit\": " << quoted(m.git_commit) << ",\n  \"git_dirty\": " << (m.git_dirty ? "true" : "false")
      << ",\n  \"machine\": {\"cpu_model\": " << quoted(m.cpu_model)
      << ", \"cores\": " << m.cores << ", \"load_average_1min\": " << number(m.load_1min) << "},\n"
      << "  \"scenario\": " << quoted(f.scenario) << ",\n  \"steps\": " << f.steps << ",\n  \"dt_s\": " << number(f.dt_s)
      << ",\n  \"layouts\": {";
    for (std::size_t i = 0; i < f.layouts.size(); ++i)
        o << (i ? "," : "") << "\n    " << quoted(f.layouts[i].layout) << ": {\"steps_per_s\": "
          << number(f.layouts[i].steps_per_s) << ", \"x_real_time\": " << number(f.layouts[i].x_real_time) << "}";
    o << "\n  },\n  \"component_us_per_step\": {";
    for (std::size_t i = 0; i < f.component_us.size(); ++i)
        o << (i ? "," : "") << "\n    " << quoted(f.component_us[i].first) << ": " << number(f.component_us[i].second);
    o << "\n  },\n  \"montecarlo\": {\n    \"layout\": \"direct\",\n    \"jobs\": " << f.mc_jobs
      << ",\n    \"method\": \"a small batch (runs, steps_per_run_measured), timed without the report; runs_per_minute "
         "extrapolated to full-length runs (steps_per_run_full) in proportion to the steps\",\n    \"scenarios\": {";
    for (std::size_t i = 0; i < f.montecarlo.size(); ++i) {
        const BenchMcFigure& s = f.montecarlo[i];
        o << (i ? "," : "") << "\n      " << quoted(s.scenario) << ": {\"runs\": " << s.runs
          << ", \"steps_per_run_measured\": " << s.steps_run << ", \"steps_per_run_full\": " << s.steps_full
          << ", \"wall_s\": " << number(s.wall_s) << ", \"runs_per_minute\": " << number(s.runs_per_minute)
          << ", \"minutes_per_100_runs\": " << number(s.runs_per_minute > 0 ? 100.0 / s.runs_per_minute : NAN) << "}";
    }
    o << "\n    }\n  }\n}\n";
    return o.str();
}

}  // namespace gdnav::launch::bench
