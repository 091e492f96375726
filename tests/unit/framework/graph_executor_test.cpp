// The graph's step order and the direct executor's lag semantics and stamps, without DDS.
#include <gtest/gtest.h>

#include "framework/direct_executor.hpp"
#include "framework/graph.hpp"
#include "framework/run_config.hpp"
#include "probe_chain.hpp"

using namespace gdnav;
using namespace gdnav::framework;
using namespace gdnav::framework::test;

TEST(Graph, StepOrderFollowsZeroLagEdgesWhateverTheInputOrder) {
    ComponentRegistry reg;
    testchain::register_chain(reg);
    const RunConfig rc = RunConfig::parse(kChain, "chain");
    auto comps = rc.build(reg);
    std::vector<Component*> raw;
    for (auto it = comps.rbegin(); it != comps.rend(); ++it) raw.push_back(it->get());
    const Graph g = build_graph(raw);
    std::vector<std::string> names;
    for (auto* c : g.order) names.push_back(c->name());
    EXPECT_EQ(names, (std::vector<std::string>{"chain_plant", "chain_sensor", "chain_filter", "chain_controller"}));
}

TEST(Graph, ZeroLagCycleIsRejected) {
    Source a("a");
    class Loop final : public Component {
    public:
        using Component::Component;
        void configure(const config::Config&, const RunInfo&, rnd::Stream&) override {}
        void step(const StepContext&) override {}
        Input<testchain::ChainControl> in_{*this, "probe/a"};
        Output<testchain::ChainState> out_{*this, "probe/b"};
    } b("b");
    class Back final : public Component {
    public:
        using Component::Component;
        void configure(const config::Config&, const RunInfo&, rnd::Stream&) override {}
        void step(const StepContext&) override {}
        Input<testchain::ChainState> in_{*this, "probe/b"};
        Output<testchain::ChainMeas> out_{*this, "probe/c"};
    } c("c");
    class Closer final : public Component {
    public:
        using Component::Component;
        void configure(const config::Config&, const RunInfo&, rnd::Stream&) override {}
        void step(const StepContext&) override {}
        Input<testchain::ChainMeas> in_{*this, "probe/c"};
        Output<testchain::ChainControl> out_{*this, "probe/a"};
    } d("d");
    EXPECT_THROW(build_graph({&b, &c, &d}), std::runtime_error);
    EXPECT_THROW(build_graph({&a, &d}), std::runtime_error);  // two producers of probe/a
}

TEST(DirectExecutor, SameLagSeesStepKPreviousLagSeesStepKMinusOne) {
    std::vector<std::unique_ptr<Component>> v;
    v.push_back(std::make_unique<Sink>("same", Lag::Same));
    v.push_back(std::make_unique<Sink>("prev", Lag::Previous));
    v.push_back(std::make_unique<Source>("src"));
    auto* same = static_cast<Sink*>(v[0].get());
    auto* prev = static_cast<Sink*>(v[1].get());
    RunInfo info;
    info.steps = 4;
    DirectExecutor ex(std::move(v), info);
    ex.run();
    EXPECT_EQ(same->seen, (std::vector<double>{0, 1, 2, 3}));
    EXPECT_EQ(prev->seen, (std::vector<double>{-1, 0, 1, 2}));
}

TEST(DirectExecutor, OutputsAreStampedWithRunStepAndTime) {
    std::vector<std::unique_ptr<Component>> v;
    v.push_back(std::make_unique<Source>("src"));
    auto* src = static_cast<Source*>(v[0].get());
    RunInfo info;
    info.steps = 3;
    info.run_index = 7;
    info.t0_s = -50.0;
    DirectExecutor ex(std::move(v), info);
    ex.run();
    EXPECT_EQ(src->out_.value().stamp().run_id(), 7u);
    EXPECT_EQ(src->out_.value().stamp().step(), 2u);
    EXPECT_DOUBLE_EQ(src->out_.value().stamp().t_s(), -49.98);
}
