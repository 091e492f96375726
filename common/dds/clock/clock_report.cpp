// Progress lines, <out>/clock_summary.yaml and the end of the run (part of clock.cpp's Clock::Impl).
#include "dds/clock/clock_impl.hpp"

#include <filesystem>
#include <fstream>

#include <spdlog/spdlog.h>
#include <yaml-cpp/yaml.h>

namespace gdnav::runtime {

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

void Clock::Impl::write_summary(bool completed, double now) {
    if (rc.out_dir.empty()) return;
    std::error_code ec;
    std::filesystem::create_directories(rc.out_dir, ec);
    std::ofstream f(std::filesystem::path(rc.out_dir) / "clock_summary.yaml");
    const double wall = now - run_start_s;
    f << "completed: " << (completed ? "true" : "false") << "\n";
    f << "steps_done: " << (completed ? rc.info.steps : current) << "\n";
    f << "wall_s: " << wall << "\n";
    f << "steps_per_s: " << (wall > 0 ? static_cast<double>(completed ? rc.info.steps : current) / wall : 0.0) << "\n";
    if (!completed) f << "abort_reason: \"" << abort_reason << "\"\n";
    f << "dead_members:\n";
    for (Member* m : table)
        if (m->dead) f << "  - {name: " << m->name << ", step: " << m->dead_at_step << "}\n";
    f << "rejoined_members: [";
    for (std::size_t i = 0; i < rejoined.size(); ++i) f << (i ? ", " : "") << rejoined[i];
    f << "]\n";
    // A free-running member that writes, or a member declared dead at a wall-clock moment, makes the outputs
    // timing-dependent; an observer (free, no outputs) does not.
    bool timing = !rejoined.empty();
    for (Member* m : table) timing = timing || (m->free && !m->observer()) || m->dead;
    f << "reproducible: " << (timing ? "false" : "true") << "\n";
    // Control messages of other runs on the domain (another run token): ignored, so they change nothing.
    f << "foreign_control_messages: " << foreign.count() << "\n";
}

int Clock::Impl::finish(int code, double now) {
    if (code == kExitOk) {
        send_control(msg::RUN_STOP, "");
        log_progress(now, true);
        spdlog::info("run complete: {} steps in {:.2f} s", rc.info.steps, now - run_start_s);
    } else {
        send_control(msg::RUN_ABORT, abort_reason);
        spdlog::error("run aborted: {}", abort_reason);
    }
    foreign.report();
    write_summary(code == kExitOk, now);
    control_writer->wait_for_acknowledgments(Duration_t(2, 0));
    return code;
}

}  // namespace gdnav::runtime
