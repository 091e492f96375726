// What the clock's member table and live faults change in the host's parts: each member's place in the table, its
// inputs' producers and faults, the observers' readers, matching, a member's rejoin (part of DdsHost::Impl).
#include "dds/host/host_impl.hpp"

#include <spdlog/spdlog.h>

#include "framework/graph.hpp"

namespace gdnav::dds {

bool DdsHost::Impl::configure(const msg::RunControl& c) {
    const framework::RunInfo& ri = control.run().timing().ri;
    if (!faults.adopt(c.faults().to_string(), ri, locals)) return false;
    for (auto& l : locals) {
        l.index = control.members().index_of(l.comp->name());
        if (l.index == UINT32_MAX) {
            spdlog::error("member '{}' is not in the clock's member table (another run on this domain, or a "
                          "name the run does not expect)", l.comp->name());
            not_in_table = true;
            continue;
        }
        inputs.configure(l, control.members().entries(), faults.schedule(), ri);
    }
    drop_local_readers();
    observers.make_readers(locals, control.members().entries(), *dds,
                           [this](host::Channel& ch) { return listen(ch.fresh_flag()); });
    return true;
}

void DdsHost::Impl::drop_local_readers() {
    const auto& table = control.members().entries();
    const auto here = [this](const std::string& name) { return host::hosted_here(locals, name); };
    std::vector<std::string> dropped;
    for (auto& l : locals)
        for (host::Channel* ch : l.inputs) {
            if (ch->local_only()) continue;
            MemberNames producers;
            for (auto i : ch->producers()) producers.push_back(table[i].name().to_string());
            if (!host::read_without_dds(producers, here)) continue;
            // The channel forgets its reader before DDS unmatches it from the local writers, so that no output is
            // ever judged unread outside while an outside reader is still matched (host::read_outside).
            eprosima::fastdds::dds::DataReader* r = ch->drop_reader();
            if (r != nullptr && !dds->delete_reader(r))
                spdlog::warn("member '{}': the DDS reader of input '{}' could not be deleted; it stays, unread",
                             l.comp->name(), ch->port()->topic());
            dropped.push_back(l.comp->name() + ":" + ch->port()->topic());
        }
    if (!dropped.empty())
        spdlog::debug("host {}: inputs produced in this process only, read without DDS: {}", control.host_id(),
                      framework::join_topics(dropped));
}

bool DdsHost::Impl::live_faults(const msg::RunControl& c) {
    const framework::RunInfo& ri = control.run().timing().ri;
    const auto first = faults.adopt_live(c.faults().to_string(), ri);
    if (!first) return false;
    inputs.extend_faults(faults.schedule(), *first, control.members().entries(), ri);
    for (std::size_t i = *first; i < faults.schedule().size(); ++i) {
        const framework::faults::Fault& f = faults.schedule().faults()[i];
        if (f.kind == framework::faults::Kind::Rejoin) {
            rejoin(f);
            continue;
        }
        spdlog::warn("fault injected live: {} (step {})", f.describe(), f.from_step);
    }
    return true;
}

void DdsHost::Impl::rejoin(const framework::faults::Fault& f) {
    for (auto& l : locals)
        if (l.awaiting_rejoin && l.comp->name() == f.target) {
            l.awaiting_rejoin = false;
            l.next_step = f.from_step;
            spdlog::info("member '{}' rejoins the run at step {} (t = {:.2f} s)", f.target, f.from_step,
                         control.run().timing().ri.time_of(f.from_step));
        }
    const std::uint32_t i = control.members().index_of(f.target);
    if (i == UINT32_MAX) return;
    control.members().revive(i);
    inputs.revive(i, f.target, f.from_step);
}

bool DdsHost::Impl::all_matched() const {
    if (!inputs.matched()) return false;
    for (const auto& l : locals)
        for (const auto& o : l.outputs) {
            // An observer may read the topic's mirror instead (mirror.hpp): its reader is matched there.
            eprosima::fastdds::dds::PublicationMatchedStatus st;
            o.writer->get_publication_matched_status(st);
            // Local readers without a DDS reader (drop_local_readers) are not matched with it.
            const int dropped = static_cast<int>(o.routes.size()) - host::local_dds_readers(o);
            if (st.current_count + host::mirror_readers(o) + dropped < control.members().readers_of(o.port->topic()))
                return false;
        }
    return control.clock_matched();
}

}  // namespace gdnav::dds
