#include "dds/host/host_observers.hpp"

#include <algorithm>
#include <string>

#include <spdlog/spdlog.h>

#include "framework/stride_policy.hpp"
#include "dds/host/mirror.hpp"

namespace gdnav::dds::host {

using namespace eprosima::fastdds::dds;

bool hosted_as_observer(const framework::Component& c) { return c.observer() && c.outputs().empty(); }

void add_mirror(Output& o, DataWriter* mirror) {
    o.mirror = mirror;
    o.mirror_matched = count_matches(mirror);
}

bool mirror_due(const Output& o, std::uint64_t k) {
    return o.mirror != nullptr && k % kMirrorStride == 0 && o.mirror_matched->readers.load() > 0;
}

int mirror_readers(const Output& o) { return o.mirror ? o.mirror_matched->readers.load() : 0; }

bool step_missed(const Local& l, std::uint64_t k) {
    for (const Channel* ch : l.inputs) {
        if (ch->lost() || ch->free()) continue;
        const auto lag = static_cast<std::uint64_t>(ch->port()->lag());
        if (k < lag) continue;
        const std::uint64_t need = k - lag;
        if (!framework::on_stride(*ch->port(), need) || need < ch->lost_until()) continue;
        const std::size_t i = need % framework::kInboxRing;
        if (!ch->holds(i, need) && ch->saw_after(need)) return true;
    }
    return false;
}

void catch_up(Local& l, const Channel& ch, std::uint64_t s) {
    const auto lag = static_cast<std::uint64_t>(ch.port()->lag());
    const std::uint64_t first = s + lag + 1 - framework::kInboxRing;
    l.skipped += first - l.next_step;
    l.next_step = first;
}

DataReader* topic_reader(DdsContext& dds, const Channel& ch, bool observer) {
    return dds.reader(ch.port()->topic(), ch.ops(), kDataReaderProfile, framework::stride_of(*ch.port()), observer);
}

bool Observers::defers(const Local& l, const framework::InputBase& in) const {
    return l.observer && may_read_mirror(framework::stride_of(in), !mirrors());
}

void Observers::make_readers(std::vector<Local>& locals, const std::vector<msg::MemberInfo>& table, DdsContext& dds,
                             const std::function<DataReaderListener*(Channel&)>& listener_for) const {
    // A producer writes a mirror when it is a gdnav host in another process: configured, not external, not here.
    const auto writes_mirror = [&](const std::string& name) {
        const bool configured = std::any_of(rc_.members.begin(), rc_.members.end(),
                                            [&](const framework::MemberSpec& m) { return m.name == name; });
        return configured && !rc_.is_external(name) && !hosted_here(locals, name);
    };
    for (auto& l : locals)
        for (Channel* ch : l.inputs) {
            if (ch->reader() != nullptr || !ch->deferred()) continue;
            std::vector<std::string> names;
            for (auto i : ch->producers()) names.push_back(table[i].name().to_string());
            const std::string& topic = ch->port()->topic();
            const bool mirror = reads_mirror(framework::stride_of(*ch->port()), !mirrors(), names, writes_mirror);
            ch->set_reader(mirror ? dds.reader(mirror_topic(topic), ch->ops(), kDataReaderProfile, 1, true)
                                  : topic_reader(dds, *ch, true));
            ch->reader()->set_listener(listener_for(*ch), StatusMask::data_available());
            spdlog::debug("member '{}': input '{}' read from {}", l.comp->name(), topic,
                          mirror ? mirror_topic(topic) : "the topic itself");
        }
}

void Observers::report(const std::vector<Local>& locals, std::uint64_t steps) {
    for (const auto& l : locals) {
        if (!l.observer) continue;
        const std::uint64_t computed = l.next_step - l.skipped;
        const std::uint64_t unreached = steps > l.next_step ? steps - l.next_step : 0;  // the run ended first
        const std::string tail = unreached ? fmt::format(", {} not reached before the end", unreached) : "";
        if (l.skipped == 0 && unreached == 0)
            spdlog::info("observer '{}': computed {} of {} steps, none skipped", l.comp->name(), computed, steps);
        else
            spdlog::warn("observer '{}': computed {} of {} steps, skipped {}{} (samples lost on the best-effort "
                         "readers, or it fell behind)", l.comp->name(), computed, steps, l.skipped, tail);
    }
}

}  // namespace gdnav::dds::host
