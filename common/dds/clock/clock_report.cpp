// Progress lines, <out>/clock_summary.yaml and the end of the run (part of clock.cpp's Clock::Impl).
#include "dds/clock/clock_impl.hpp"

#include <filesystem>
#include <ostream>
#include <sstream>

#include <spdlog/spdlog.h>
#include <yaml-cpp/yaml.h>

#include "dds/process/run_cause.hpp"
#include "files/write_error.hpp"

namespace gdnav::dds {

using namespace eprosima::fastdds::dds;
using eprosima::fastrtps::Duration_t;

void Clock::Impl::log_progress(double now, bool force) {
    if (!opt.progress || (!force && now < next_log_s)) return;
    next_log_s = now + 2.0;
    const double wall = std::max(now - run_start_s, 1e-9);
    const double sps = static_cast<double>(current) / wall;
    spdlog::info("step {}/{} ({:.0f}%), t = {:.1f} s, {:.0f} steps/s, {:.1f}x real time", current, rc.info.steps,
                 100.0 * static_cast<double>(current) / static_cast<double>(rc.info.steps),
                 rc.info.time_of(current), sps, sps * rc.info.dt_s);
}

bool Clock::Impl::write_summary(bool completed, double now) {
    if (rc.out_dir.empty()) return true;
    std::error_code ec;
    std::filesystem::create_directories(rc.out_dir, ec);
    std::ostringstream f;
    const double wall = now - run_start_s;
    f << "completed: " << (completed ? "true" : "false") << "\n";
    f << "steps_done: " << (completed ? rc.info.steps : current) << "\n";
    f << "wall_s: " << wall << "\n";
    f << "steps_per_s: " << (wall > 0 ? static_cast<double>(completed ? rc.info.steps : current) / wall : 0.0) << "\n";
    // Reasons may hold any text (a member's exception): quoted by the YAML emitter.
    auto quoted = [](const std::string& text) {
        YAML::Emitter e;
        e << YAML::DoubleQuoted << text;
        return std::string(e.c_str());
    };
    if (!completed) f << "abort_reason: " << quoted(abort_reason) << "\n";
    f << "dead_members:\n";
    for (Member* m : table)
        if (m->dead)
            f << "  - {name: " << m->name << ", step: " << m->dead_at_step << ", reason: " << quoted(m->dead_reason)
              << "}\n";
    f << "rejoined_members: [";
    for (std::size_t i = 0; i < rejoined.size(); ++i) f << (i ? ", " : "") << rejoined[i];
    f << "]\n";
    // A free-running member that writes, or a member declared dead at a wall-clock moment, makes the outputs
    // timing-dependent; an observer (free, no outputs) does not.
    bool timing = !rejoined.empty();
    for (Member* m : table) timing = timing || (m->free && !m->observer()) || m->dead;
    const std::uint64_t rejected = write_rejected(f);
    f << "reproducible: " << (timing ? "false" : "true") << "\n";
    // Rejected samples were never used: the outputs are those of a run without them, which holds only as far as the
    // producers were identified right (docs/protocol.md §2.5). The claim says what `reproducible` then means.
    if (rejected > 0)
        f << "reproducible_claim: \"as a run without the " << rejected
          << " rejected samples (rejected_samples): samples not written by a topic's producer were never used, and a "
             "sample with a bad stamp counted as not available at its step\"\n";
    // Control messages of other runs on the domain (another run token): ignored, so they change nothing.
    f << "foreign_control_messages: " << foreign.count() << "\n";
    // Whole or not at all: a summary cut short by a full disk must not read as a run's (docs/runtime.md, "Exit
    // codes"). The launcher then learns the run's cause from the cause pipe.
    try {
        files::write_whole(std::filesystem::path(rc.out_dir) / "clock_summary.yaml", f.str());
    } catch (const files::WriteError& e) {
        spdlog::error("{}", e.what());
        tell_launcher(completed ? std::string(e.what()) : abort_reason);
        return false;
    }
    return true;
}

std::uint64_t Clock::Impl::write_rejected(std::ostream& f) const {
    // Each member's latest heartbeat: "TOPIC:NOT_FROM_PRODUCER:BAD_STAMP,..." (dds/host/host_inbox.hpp).
    std::string lines;
    std::uint64_t total = 0;
    for (const Member* m : table) {
        std::size_t b = 0;
        while (b < m->rejected.size()) {
            std::size_t e = m->rejected.find(',', b);
            if (e == std::string::npos) e = m->rejected.size();
            const std::string entry = m->rejected.substr(b, e - b);
            b = e + 1;
            const std::size_t c2 = entry.rfind(':');
            const std::size_t c1 = c2 == std::string::npos || c2 == 0 ? std::string::npos : entry.rfind(':', c2 - 1);
            if (c1 == std::string::npos) continue;
            const std::string foreign = entry.substr(c1 + 1, c2 - c1 - 1), bad = entry.substr(c2 + 1);
            if (foreign.empty() || bad.empty() || foreign.find_first_not_of("0123456789") != std::string::npos ||
                bad.find_first_not_of("0123456789") != std::string::npos)
                continue;  // not a count this clock understands
            total += std::stoull(foreign) + std::stoull(bad);
            lines += "  - {member: \"" + m->name + "\", topic: \"" + entry.substr(0, c1) + "\", not_from_producer: " +
                     foreign + ", bad_stamp: " + bad + "}\n";
        }
    }
    f << "rejected_samples:" << (lines.empty() ? " []\n" : "\n" + lines);
    return total;
}

int Clock::Impl::finish(int code, double now) {
    if (code == framework::kExitOk) {
        send_control(msg::RUN_STOP, "");
        log_progress(now, true);
        spdlog::info("run complete: {} steps in {:.2f} s", rc.info.steps, now - run_start_s);
    } else {
        send_control(msg::RUN_ABORT, abort_reason);
        spdlog::error("run aborted: {}", abort_reason);
    }
    foreign.report();
    if (!write_summary(code == framework::kExitOk, now) && code == framework::kExitOk)
        code = framework::kExitWriteFailed;
    control_writer->wait_for_acknowledgments(Duration_t(2, 0));
    return code;
}

}  // namespace gdnav::dds
