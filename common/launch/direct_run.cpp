// The direct layout (launch/launcher.hpp, run_direct): every component in this process, one thread, no transport.
#include <algorithm>
#include <filesystem>
#include <sstream>
#include <string>

#include <spdlog/spdlog.h>

#include "dds/process/process_signals.hpp"
#include "files/write_error.hpp"
#include "framework/direct_executor.hpp"
#include "framework/lockstep.hpp"
#include "launch/launcher.hpp"

namespace gdnav::launch {

namespace fs = std::filesystem;

namespace {
// <out>/clock_summary.yaml of a direct run, in the clock's layout (docs/protocol.md §5): `head` (completed,
// steps_done and what goes with them), then the lines every direct run has in common: no member can die or rejoin
// and nothing runs free, so the run is reproducible.
// Written whole or not at all (files::write_whole); a WriteError ends the run like a member's.
void write_direct_summary(const framework::RunConfig& rc, const std::string& head) {
    if (rc.out_dir.empty()) return;
    files::write_whole(fs::path(rc.out_dir) / "clock_summary.yaml", head + "dead_members: []\nreproducible: true\n");
}

int run_direct_steps(const framework::RunConfig& rc, const framework::ComponentRegistry& reg, bool progress,
                     double* steps_per_s);
}  // namespace

int run_direct(const framework::RunConfig& rc, const framework::ComponentRegistry& reg, bool progress,
               double* steps_per_s) {
    try {
        return run_direct_steps(rc, reg, progress, steps_per_s);
    } catch (const files::WriteError& e) {
        // The run's last line names the file and the OS error, as the launcher's does in the other layouts.
        spdlog::error("run failed (exit code {}): {}", framework::kExitWriteFailed, e.what());
        return framework::kExitWriteFailed;
    }
}

namespace {
int run_direct_steps(const framework::RunConfig& rc, const framework::ComponentRegistry& reg, bool progress,
                     double* steps_per_s) {
    auto comps = rc.build(reg);
    framework::DirectExecutor ex(std::move(comps), rc.info);
    ex.set_faults(rc.faults, [&rc, &reg](const std::string& name) { return rc.build_one(reg, name); });
    // An essential member killed by a scheduled fault ends the run at that step, as the clock does.
    std::uint64_t abort_at = rc.info.steps;
    std::string abort_reason;
    for (const auto& f : rc.faults.faults())
        if (f.kind == framework::faults::Kind::Kill && f.from_step < abort_at &&
            std::find(rc.essential.begin(), rc.essential.end(), f.target) != rc.essential.end()) {
            abort_at = f.from_step;
            abort_reason = "essential member '" + f.target + "' killed by a scheduled fault at step " +
                           std::to_string(f.from_step);
        }
    dds::install_stop_signal_handlers();
    const double t0 = framework::steady_now_s();
    double next_log = t0 + 2.0;
    const std::uint64_t done = ex.run(
        [&](std::uint64_t k) {
            if (abort_at < rc.info.steps && k >= abort_at) return false;
            if (dds::stop_requested()) return false;
            if (!progress) return true;
            const double now = framework::steady_now_s();
            if (now < next_log) return true;
            next_log = now + 2.0;
            const double sps = static_cast<double>(k) / (now - t0);
            spdlog::info("step {}/{} ({:.0f}%), t = {:.1f} s, {:.0f} steps/s, {:.0f}x real time", k, rc.info.steps,
                         100.0 * static_cast<double>(k) / static_cast<double>(rc.info.steps), rc.info.time_of(k), sps,
                         sps * rc.info.dt_s);
            return true;
        },
        abort_at < rc.info.steps ? 1 : 100);
    if (done == abort_at && abort_at < rc.info.steps) {
        spdlog::error("run aborted: {}", abort_reason);
        write_direct_summary(rc, "completed: false\nsteps_done: " + std::to_string(done) + "\nabort_reason: \"" +
                                     abort_reason + "\"\n");
        return framework::kExitAborted;
    }
    if (done < rc.info.steps) {
        spdlog::error("run interrupted by signal {} at step {}", dds::stop_signal(), done);
        return framework::kExitInterrupted;
    }
    const double wall = framework::steady_now_s() - t0;
    const double sps = static_cast<double>(rc.info.steps) / std::max(wall, 1e-9);
    if (steps_per_s) *steps_per_s = sps;
    if (progress)
        spdlog::info("run complete: {} steps in {:.2f} s ({:.0f} steps/s, {:.0f}x real time)", rc.info.steps, wall, sps,
                     sps * rc.info.dt_s);
    std::ostringstream head;
    head << "completed: true\nsteps_done: " << rc.info.steps << "\nwall_s: " << wall << "\nsteps_per_s: " << sps << "\n";
    write_direct_summary(rc, head.str());
    return framework::kExitOk;
}
}  // namespace

}  // namespace gdnav::launch
