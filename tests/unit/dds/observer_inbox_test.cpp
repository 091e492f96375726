// An observer's lost-step rule (dds/host/host_observers.hpp, dds::host::step_missed): a step is given up only when an
// input it reads has no sample of that step while a newer sample of the same input has arrived (one writer's samples
// arrive in order). Inboxes filled by hand, no DDS.
#include <gtest/gtest.h>

#include "chain_components.hpp"
#include "dds/host/host_observers.hpp"

using namespace gdnav;
using namespace gdnav::framework;

namespace {

class Watcher final : public Component {
public:
    explicit Watcher(Lag lag) : Component("watcher"), a_(*this, "probe/a", lag), b_(*this, "probe/b") {}
    void configure(const config::Config&, const RunInfo&, rnd::Stream&) override {}
    void step(const StepContext&) override {}
    Input<testchain::ChainControl> a_;
    Input<testchain::ChainControl> b_;
};

struct Inboxes {
    explicit Inboxes(Lag lag_a) : w(lag_a), a(w.a_), b(w.b_) {
        l.comp = &w;
        l.observer = true;
        l.inputs = {&a, &b};
    }
    static void put(gdnav::dds::host::Channel& ch, std::uint64_t s) {  // as dds::host::Inputs::read files a sample
        ch.saw(s);
        ch.file_taken(s % kInboxRing, s, true);
    }
    Watcher w;
    gdnav::dds::host::Channel a, b;
    gdnav::dds::host::Local l;
};

}  // namespace

TEST(ObserverInbox, AStepStillInFlightIsWaitedForAndALostOneIsGivenUp) {
    Inboxes in(Lag::Same);
    Inboxes::put(in.a, 5);
    EXPECT_FALSE(gdnav::dds::host::step_missed(in.l, 5));  // b's sample of step 5 may still come
    Inboxes::put(in.b, 6);                                 // b's writer is past 5: its sample of step 5 was lost
    EXPECT_TRUE(gdnav::dds::host::step_missed(in.l, 5));
    Inboxes::put(in.a, 6);
    EXPECT_FALSE(gdnav::dds::host::step_missed(in.l, 6));  // both here
    EXPECT_FALSE(gdnav::dds::host::step_missed(in.l, 7));  // nothing newer than 6 anywhere: wait
}

TEST(ObserverInbox, LagStrideAndLostInputsAreRespected) {
    Inboxes in(Lag::Previous);  // a is read at k - 1
    Inboxes::put(in.a, 9);
    Inboxes::put(in.b, 10);
    EXPECT_FALSE(gdnav::dds::host::step_missed(in.l, 10));  // a of step 9 and b of step 10: step 10 is complete
    Inboxes::put(in.a, 11);
    EXPECT_TRUE(gdnav::dds::host::step_missed(in.l, 11));  // a of step 10 is missing and a of step 11 has arrived

    Inboxes st(Lag::Same);
    st.w.a_.set_stride(10);
    st.w.b_.set_stride(10);
    Inboxes::put(st.a, 20);
    Inboxes::put(st.b, 20);
    EXPECT_FALSE(gdnav::dds::host::step_missed(st.l, 15));  // not a step the strided inputs read: nothing is missing
    EXPECT_TRUE(gdnav::dds::host::step_missed(st.l, 10));  // step 10 never came, step 20 did

    Inboxes lost(Lag::Same);
    Inboxes::put(lost.a, 3);
    lost.b.mark_lost();  // its producer was declared dead: not waited for, not missing
    EXPECT_FALSE(gdnav::dds::host::step_missed(lost.l, 3));
}
