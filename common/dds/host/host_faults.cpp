#include "dds/host/host_faults.hpp"

#include <algorithm>

#include <spdlog/spdlog.h>

namespace gdnav::dds::host {

namespace {

// The schedule in `yaml`; none (logged) when it cannot be read.
std::optional<framework::faults::FaultSchedule> read_schedule(const std::string& yaml, const framework::RunInfo& ri) {
    try {
        return framework::faults::FaultSchedule::from_yaml(yaml, ri);
    } catch (const std::exception& e) {
        spdlog::error("cannot apply the clock's fault schedule: {}", e.what());
        return std::nullopt;
    }
}

}  // namespace

bool Faults::adopt(const std::string& yaml, const framework::RunInfo& ri, const std::vector<Local>& locals) {
    auto read = read_schedule(yaml, ri);
    if (!read) return false;
    schedule_ = std::move(*read);
    for (const auto& f : schedule_.faults())
        for (const auto& l : locals)
            if (f.kind == framework::faults::Kind::Kill && f.target == l.comp->name() && f.until_step < ri.steps &&
                !rebuild_) {
                spdlog::error("member '{}' cannot be restarted by the scheduled {} (this host cannot create it "
                              "anew)", l.comp->name(), f.describe());
                return false;
            }
    return true;
}

std::optional<std::size_t> Faults::adopt_live(const std::string& yaml, const framework::RunInfo& ri) {
    const auto longer = read_schedule(yaml, ri);
    if (!longer) return std::nullopt;
    return schedule_.adopt(*longer);
}

void Faults::restart(Local& l, std::uint64_t k, std::vector<std::unique_ptr<framework::Component>>& owned,
                     ControlPlane& control) {
    const std::string name = l.comp->name();  // a copy: the old member is destroyed below
    l.restarted_at = k;
    std::unique_ptr<framework::Component> fresh = rebuild_(name);
    for (std::size_t n = 0; n < l.inputs.size(); ++n) l.inputs[n]->rebind(*fresh->inputs()[n]);
    for (std::size_t n = 0; n < l.outputs.size(); ++n) l.outputs[n].port = fresh->outputs()[n];
    for (auto& c : owned)
        if (c.get() == l.comp) c = std::move(fresh), l.comp = c.get();
    l.killed = false;
    spdlog::warn("[{}] step {} t={:.2f} s: restarted by a scheduled fault (created anew)", name, k,
                 control.run().timing().ri.time_of(k));
    control.send_status(l, msg::STATUS_MODE, "restarted by a scheduled fault");
}

bool Faults::apply(Local& l, std::uint64_t k, std::vector<std::unique_ptr<framework::Component>>& owned,
                   ControlPlane& control) {
    if (l.restarted_at != k && schedule_.restarts_at(l.comp->name(), k)) restart(l, k, owned, control);
    const std::string& name = l.comp->name();
    if (!schedule_.killed(name, k)) return true;
    const RunTiming& t = control.run().timing();
    if (!l.killed) {
        l.killed = true;
        spdlog::warn("[{}] step {} t={:.2f} s: killed by a scheduled fault", name, k, t.ri.time_of(k));
        control.send_status(l, msg::STATUS_MODE, "killed by a scheduled fault");
        // The clock stops waiting for it from step k on: report the steps done before (done_every cadence).
        if (k > 0 && l.barrier && k % t.done_every != 0) control.send_done(l, k - 1);
    }
    l.next_step = std::min(schedule_.alive_again(name, k), t.ri.steps);
    return false;
}

}  // namespace gdnav::dds::host
