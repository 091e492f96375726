#include "dds/host/host_inputs.hpp"

#include <algorithm>
#include <cmath>
#include <sstream>

#include <fastdds/dds/subscriber/SampleInfo.hpp>
#include <spdlog/spdlog.h>

#include "framework/stride_policy.hpp"
#include "dds/host/host_observers.hpp"
#include "framework/executor_access.hpp"
#include "framework/graph.hpp"

namespace gdnav::dds::host {

using namespace eprosima::fastdds::dds;

namespace {

// The faults of `schedule` on input `ch` (nullptr when none concerns it).
std::unique_ptr<framework::faults::InputFaults> input_faults(const Channel& ch,
                                                             const framework::faults::FaultSchedule& schedule,
                                                             const std::vector<msg::MemberInfo>& table,
                                                             const framework::RunInfo& ri) {
    std::vector<std::string> names;
    for (auto i : ch.producers()) names.push_back(table[i].name().to_string());
    auto f = std::make_unique<framework::faults::InputFaults>(schedule, ch.port()->topic(), names, ch.ops(), ri);
    if (f->empty()) f.reset();
    return f;
}

}  // namespace

Channel* Inputs::add(framework::InputBase* in) {
    channels_.push_back(std::make_unique<Channel>(*in));
    return channels_.back().get();
}

void Inputs::identify(const Participants* known, std::function<bool(const std::string&)> must_announce) {
    known_ = known;
    must_announce_ = std::move(must_announce);
}

std::vector<DataReader*> Inputs::readers() const {
    std::vector<DataReader*> v;
    for (const auto& c : channels_)
        if (c->reader() != nullptr) v.push_back(c->reader());
    return v;
}

void Inputs::configure(const Local& l, const std::vector<msg::MemberInfo>& table,
                       const framework::faults::FaultSchedule& schedule, const framework::RunInfo& ri) {
    for (Channel* ch : l.inputs) {
        std::vector<std::uint32_t> producers;
        MemberNames names;
        std::vector<bool> announce;
        bool runs_free = free_running_;
        for (std::uint32_t i = 0; i < table.size(); ++i) {
            const auto outs = framework::split_topics(table[i].outputs().to_string());
            if (std::find(outs.begin(), outs.end(), ch->port()->topic()) != outs.end()) {
                producers.push_back(i);
                runs_free = runs_free || table[i].free_running();
                names.push_back(table[i].name().to_string());
                announce.push_back(must_announce_ && must_announce_(names.back()));
            }
        }
        ch->set_producers(std::move(producers), std::move(names), std::move(announce), known_, runs_free);
        if (!schedule.empty()) ch->set_faults(input_faults(*ch, schedule, table, ri));
        if (ch->producers().empty()) {
            spdlog::warn("member '{}': no member of this run produces '{}'; input treated as lost", l.comp->name(),
                         ch->port()->topic());
            ch->mark_lost();
        }
    }
}

bool Inputs::matched() const {
    for (const auto& ch : channels_) {
        if (ch->local_only()) continue;
        SubscriptionMatchedStatus st;
        ch->reader()->get_subscription_matched_status(st);
        if (st.current_count < static_cast<int>(ch->producers().size())) return false;
    }
    return true;
}

void Inputs::read(Local& l, Channel& ch, const framework::RunInfo& ri) {
    if (ch.reader() == nullptr) return;  // an observer's input before CONFIGURE (host_observers.hpp)
    const msg::MessageOps& ops = ch.ops();
    SampleInfo info;
    while (ch.reader()->take_next_sample(ch.scratch(), &info) == ReturnCode_t::RETCODE_OK) {
        if (!info.valid_data || ops.run_of(ch.scratch()) != ri.run_index) continue;
        if (!ch.producer().configured()) continue;  // before the member table no step can need a sample
        const GuidPrefix& from = info.sample_identity.writer_guid().guidPrefix;
        const std::uint64_t s = ops.step_of(ch.scratch());
        if (!ch.from_producer(from)) {
            reject_foreign(l, ch, from, s);
            continue;
        }
        const double t_s = ops.time_of(ch.scratch());
        const bool finite = std::isfinite(t_s);
        if (s >= ri.steps || (ch.free() && !finite)) {
            reject_stamp(l, ch, s, t_s, s >= ri.steps ? "a step beyond the run" : "t_s not finite");
            continue;
        }
        if (ch.free()) {
            ch.keep_latest(ch.scratch());
            continue;
        }
        if (l.observer) ch.saw(s);  // only an observer's lost-step test reads it
        long at = inbox_index(ch, l.next_step, s);
        if (at == kOlder) continue;
        if (at == kTooFar && l.observer) {
            catch_up(l, ch, s);
            at = inbox_index(ch, l.next_step, s);
        }
        if (at == kTooFar) {
            if (!l.killed) reject_stamp(l, ch, s, t_s, "a step too far ahead");  // a killed member reads nothing
            continue;
        }
        ch.file_taken(static_cast<std::size_t>(at), s, finite);  // a bad one too: the step does not wait for it
        if (!finite) reject_stamp(l, ch, s, t_s, "t_s not finite");
    }
}

void Inputs::reject_foreign(const Local& l, Channel& ch, const GuidPrefix& from, std::uint64_t s) {
    if (const std::uint64_t n = ch.reject_foreign(framework::steady_now_s())) {
        std::ostringstream who;
        who << from;
        spdlog::warn("member '{}', input '{}': {} sample(s) not written by its producer ({}) dropped, {} in all (the "
                     "last: step {}, from participant {})",
                     l.comp->name(), ch.port()->topic(), n, ch.producer().names(), ch.foreign().total(), s,
                     who.str());
    }
}

void Inputs::reject_stamp(const Local& l, Channel& ch, std::uint64_t s, double t_s, const char* why) {
    if (const std::uint64_t n = ch.reject_stamp(framework::steady_now_s()))
        spdlog::warn("member '{}', input '{}': {} sample(s) with a bad stamp rejected, {} in all (the last: step {}, "
                     "t_s {}: {}; its step is {})",
                     l.comp->name(), ch.port()->topic(), n, ch.bad_stamp().total(), s, t_s, why, l.next_step);
}

void Inputs::warn_too_far(const Local& l, Channel& ch, std::uint64_t s) {
    if (l.killed) return;  // a member killed by a fault does not read its inputs
    if (const std::uint64_t n = ch.drop_too_far(framework::steady_now_s()))
        spdlog::warn("input '{}': {} sample(s) too far ahead of step {} dropped, {} in all (the last: step {})",
                     ch.port()->topic(), n, l.next_step, ch.too_far_local().total(), s);
}

bool Inputs::ready(const Local& l, std::uint64_t k) const {
    for (Channel* ch : l.inputs) {
        framework::InputBase& port = *ch->port();
        if (ch->lost()) {
            framework::ExecutorAccess::bind(port, nullptr);
            continue;
        }
        if (ch->free()) {
            framework::ExecutorAccess::bind(port, ch->has_latest() ? ch->latest() : nullptr);
            continue;
        }
        const std::uint64_t lag = static_cast<std::uint64_t>(port.lag());
        if (k < lag) {
            framework::ExecutorAccess::bind(port, nullptr);
            continue;
        }
        const std::uint64_t need = k - lag;
        if (!framework::on_stride(port, need)) {  // not a step it reads: nothing sent, nothing to wait for
            framework::ExecutorAccess::bind(port, nullptr);
            continue;
        }
        if (need < ch->lost_until()) {  // its producer was dead then
            framework::ExecutorAccess::set_lost(port, true);
            continue;
        }
        if (ch->revived()) framework::ExecutorAccess::set_lost(port, false);
        framework::faults::InputFaults* f = ch->faults();
        if (f != nullptr && f->producer_killed(need)) {  // nothing was published: do not wait
            framework::ExecutorAccess::set_lost(port, true);
            continue;
        }
        const std::size_t i = need % framework::kInboxRing;
        if (!ch->holds(i, need)) return false;
        if (ch->bad(i)) {  // rejected (a bad stamp): not available at this step, as a dropped sample
            framework::ExecutorAccess::bind(port, nullptr);
            continue;
        }
        if (f != nullptr) {
            const auto d = f->apply(need, ch->slot(i));
            framework::ExecutorAccess::set_lost(port, d.lost);
            framework::ExecutorAccess::bind(port, d.data);
            continue;
        }
        framework::ExecutorAccess::bind(port, ch->slot(i));
    }
    return true;
}

void Inputs::record_lateness(const Local& l, std::uint64_t k) const {
    if (free_running_) return;  // a free-running member's own inputs are not a deadline
    for (Channel* ch : l.inputs) {
        if (!ch->free() || ch->lost()) continue;
        if (!ch->has_latest()) {
            ch->note_lateness(-1);
            continue;
        }
        const auto need = static_cast<std::int64_t>(k) - static_cast<std::int64_t>(ch->port()->lag());
        const auto have = static_cast<std::int64_t>(ch->ops().step_of(ch->latest()));
        ch->note_lateness(std::max<std::int64_t>(need - have, 0));  // a newer sample than needed is on time
    }
}

void Inputs::apply_dead_mask(std::uint64_t dead_mask) {
    for (auto& ch : channels_) {
        if (ch->lost() || ch->producers().empty()) continue;
        bool all_dead = true;
        for (auto i : ch->producers()) all_dead = all_dead && ((dead_mask >> i) & 1u);
        if (all_dead) {
            ch->mark_lost();
            spdlog::warn("input '{}' lost: its producer was declared dead", ch->port()->topic());
        }
    }
}

void Inputs::revive(std::uint32_t i, const std::string& name, std::uint64_t from_step) {
    for (auto& ch : channels_) {
        const auto& producers = ch->producers();
        if (!ch->lost() || std::find(producers.begin(), producers.end(), i) == producers.end()) continue;
        ch->revive(from_step);
        spdlog::info("input '{}': its producer '{}' rejoins at step {}", ch->port()->topic(), name, from_step);
    }
}

void Inputs::extend_faults(const framework::faults::FaultSchedule& schedule, std::size_t first,
                           const std::vector<msg::MemberInfo>& table, const framework::RunInfo& ri) {
    for (auto& ch : channels_) {
        if (ch->producers().empty()) continue;
        if (ch->faults() != nullptr)
            ch->faults()->extend(first);
        else
            ch->set_faults(input_faults(*ch, schedule, table, ri));
    }
}

void Inputs::report_rejected(const std::vector<Local>& locals) {
    for (const auto& l : locals)
        for (const Channel* ch : l.inputs)
            if (ch->foreign().total() > 0 || ch->bad_stamp().total() > 0)
                spdlog::warn("member '{}', input '{}': rejected {} sample(s) not written by its producer ({}) and {} "
                             "with a bad stamp",
                             l.comp->name(), ch->port()->topic(), ch->foreign().total(), ch->producer().names(),
                             ch->bad_stamp().total());
}

void Inputs::report_lateness(const std::vector<Local>& locals, const std::string& out_dir) const {
    if (free_running_) return;  // a free-running member's own inputs are not a deadline
    for (const auto& l : locals) {
        std::vector<std::pair<std::string, const framework::Lateness*>> inputs;
        for (const Channel* ch : l.inputs)
            if (ch->free()) inputs.emplace_back(ch->port()->topic(), &ch->lateness());
        framework::report_lateness(l.comp->name(), inputs, out_dir);
    }
}

}  // namespace gdnav::dds::host
