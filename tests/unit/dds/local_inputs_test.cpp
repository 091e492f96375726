// Inputs produced in the host's own process are read without DDS (dds/host/host_inbox.hpp, read_without_dds): the
// rule, and what dropping their readers does to the test that decides whether an output is also published on DDS
// (read_outside: a matched reader beyond the local readers that still have a DDS reader). Inboxes only, no DDS.
#include <gtest/gtest.h>

#include <set>

#include "chain_components.hpp"
#include "dds/host/host_inbox.hpp"

using namespace gdnav;
using namespace gdnav::framework;
namespace host = gdnav::dds::host;

namespace {

class Reader final : public Component {
public:
    Reader() : Component("reader"), in_(*this, "probe/a") {}
    void configure(const config::Config&, const RunInfo&, rnd::Stream&) override {}
    void step(const StepContext&) override {}
    Input<testchain::ChainControl> in_;
};

}  // namespace

TEST(LocalInputs, AnInputIsReadWithoutDdsOnlyWhenEveryProducerIsInThisProcess) {
    const std::set<std::string> here{"flight_physics", "sensors_inertial"};
    const auto is_here = [&](const std::string& n) { return here.count(n) > 0; };
    EXPECT_TRUE(host::read_without_dds({"flight_physics"}, is_here));
    EXPECT_TRUE(host::read_without_dds({"flight_physics", "sensors_inertial"}, is_here));
    // A producer in another process, or an external member: the input keeps its DDS reader.
    EXPECT_FALSE(host::read_without_dds({"flight_physics", "control"}, is_here));
    EXPECT_FALSE(host::read_without_dds({"control"}, is_here));
    // Nobody produces it (a lost input): nothing to decide, the reader stays as made.
    EXPECT_FALSE(host::read_without_dds({}, is_here));
}

TEST(LocalInputs, ADroppedReaderIsNoLongerCountedAmongTheWritersLocalMatches) {
    Reader a, b;
    host::Channel ca(a.in_), cb(b.in_);
    int token = 0;  // stands for a DDS reader: only compared with nullptr here
    auto* fake = reinterpret_cast<eprosima::fastdds::dds::DataReader*>(&token);
    ca.set_reader(fake);
    cb.set_reader(fake);
    host::Output o;
    o.routes = {{0, &ca}, {1, &cb}};
    o.matched = std::make_unique<host::MatchCount>();

    // Both local readers matched over DDS and nobody outside: not published.
    o.matched->readers.store(2);
    EXPECT_EQ(host::local_dds_readers(o), 2);
    EXPECT_FALSE(host::read_outside(o));
    // One more match: a reader outside the process.
    o.matched->readers.store(3);
    EXPECT_TRUE(host::read_outside(o));

    // b is produced here only: its reader is dropped (and returned for deletion), the channel says so.
    EXPECT_EQ(cb.drop_reader(), fake);
    EXPECT_TRUE(cb.local_only());
    EXPECT_EQ(cb.reader(), nullptr);
    EXPECT_EQ(host::local_dds_readers(o), 1);
    // Until DDS unmatches it the writer still counts it: judged read outside (published, harmless), never the reverse.
    EXPECT_TRUE(host::read_outside(o));
    o.matched->readers.store(1);  // unmatched: only a's reader is left
    EXPECT_FALSE(host::read_outside(o));
    o.matched->readers.store(2);  // an outside reader again
    EXPECT_TRUE(host::read_outside(o));
    // Dropped twice: nothing more to delete.
    EXPECT_EQ(cb.drop_reader(), nullptr);
}
