#include "dds/host/host_inbox.hpp"

#include <algorithm>

#include <fastdds/dds/core/status/PublicationMatchedStatus.hpp>

#include "framework/stride_policy.hpp"

namespace gdnav::dds::host {

Channel::Channel(framework::InputBase& in)
    : port_(&in), ops_(&in.ops()), scratch_(ops_->create()), latest_(ops_->create()) {
    for (auto& s : slot_) s = ops_->create();
}

Channel::~Channel() {
    ops_->destroy(scratch_);
    ops_->destroy(latest_);
    for (void* s : slot_) ops_->destroy(s);
}

long inbox_index(const Channel& ch, std::uint64_t next_step, std::uint64_t s) {
    const auto lag = static_cast<std::uint64_t>(ch.port()->lag());
    const std::uint64_t oldest = next_step >= lag ? next_step - lag : 0;
    if (s < oldest) return kOlder;
    if (s >= oldest + framework::kInboxRing) return kTooFar;
    return static_cast<long>(s % framework::kInboxRing);
}

std::string rejected_note(const Local& l) {
    std::string note;
    for (const Channel* ch : l.inputs) {
        if (ch->foreign().total() == 0 && ch->bad_stamp().total() == 0) continue;
        const std::string entry = ch->port()->topic() + ":" + std::to_string(ch->foreign().total()) + ":" +
                                  std::to_string(ch->bad_stamp().total());
        if (note.size() + entry.size() + 10 > 1024) break;  // ComponentStatus.message is a string<1024>
        note += (note.empty() ? "rejected " : ",") + entry;
    }
    return note;
}

void route_locally(std::vector<Local>& locals) {
    for (auto& producer : locals)
        for (auto& o : producer.outputs) {
            o.routes.clear();
            for (std::size_t c = 0; c < locals.size(); ++c)
                for (Channel* ch : locals[c].inputs)
                    if (ch->port()->topic() == o.port->topic()) o.routes.push_back({c, ch});
        }
}

bool hand_over(const Route& r, const Local& consumer, const void* sample, std::uint64_t s) {
    Channel& ch = *r.channel;
    if (ch.free()) {
        ch.keep_latest(sample);
        return true;
    }
    // a step the reader does not read (as the DDS stride filter)
    if (!framework::on_stride(*ch.port(), s)) return true;
    if (consumer.observer) ch.saw(s);  // only an observer's lost-step test reads it
    const long i = inbox_index(ch, consumer.next_step, s);
    if (i == kOlder) return true;  // no step of the reader needs it (as with a DDS sample)
    if (i == kTooFar) return false;
    ch.file_copy(static_cast<std::size_t>(i), sample, s);
    return true;
}

std::unique_ptr<MatchCount> count_matches(eprosima::fastdds::dds::DataWriter* writer) {
    auto m = std::make_unique<MatchCount>();
    writer->set_listener(m.get(), eprosima::fastdds::dds::StatusMask::publication_matched());
    eprosima::fastdds::dds::PublicationMatchedStatus st;  // matches made before the listener was set
    writer->get_publication_matched_status(st);
    m->readers.store(st.current_count);
    return m;
}

Output make_output(framework::OutputBase* port, eprosima::fastdds::dds::DataWriter* writer) {
    return Output{port, writer, {}, count_matches(writer), nullptr, nullptr};
}

bool hosted_here(const std::vector<Local>& locals, const std::string& name) {
    return std::any_of(locals.begin(), locals.end(), [&](const Local& l) { return l.comp->name() == name; });
}

int local_dds_readers(const Output& o) {
    return static_cast<int>(
        std::count_if(o.routes.begin(), o.routes.end(), [](const Route& r) { return r.channel->reader() != nullptr; }));
}

bool read_outside(const Output& o) { return o.matched->readers.load() > local_dds_readers(o); }

bool read_without_dds(const MemberNames& producers, const std::function<bool(const std::string&)>& here) {
    return !producers.empty() && std::all_of(producers.begin(), producers.end(), here);
}

}  // namespace gdnav::dds::host
