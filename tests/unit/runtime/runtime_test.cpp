// Runtime without DDS: graph order, feedback lag semantics, run-config validation, shm name filter.
#include <gtest/gtest.h>

#include "chain_components.hpp"
#include "recorder.hpp"
#include "framework/direct_executor.hpp"
#include "framework/graph.hpp"
#include "framework/run_config.hpp"
#include "launch/shm_cleanup.hpp"

using namespace gdnav;
using namespace gdnav::runtime;

namespace {

// A probe that records what it saw on its inputs.
class Source final : public Component {
public:
    using Component::Component;
    void configure(const config::Config&, const RunInfo&, rnd::Stream&) override {}
    void step(const StepContext& ctx) override { out_.value().u_mps2(static_cast<double>(ctx.k)); }
    Output<testchain::ChainControl> out_{*this, "probe/a"};
};

class Sink final : public Component {
public:
    Sink(std::string n, Lag lag) : Component(std::move(n)), in_(*this, "probe/a", lag) {}
    void configure(const config::Config&, const RunInfo&, rnd::Stream&) override {}
    void step(const StepContext&) override { seen.push_back(in_.available() ? in_.get().u_mps2() : -1.0); }
    Input<testchain::ChainControl> in_;
    std::vector<double> seen;
};

const char* kChain = R"(
run: {seed: 5, steps: 50}
components:
  chain_plant: {type: chain_plant, sigma_w_mps2: 0.5, damping_per_s: 0.2, x0_m: 3.0}
  chain_sensor: {type: chain_sensor, sigma_m: 0.1}
  chain_filter: {type: chain_filter, alpha: 0.2, beta: 0.02}
  chain_controller: {type: chain_controller, kp: 1.0, kd: 1.5, target_m: 0.0}
)";

}  // namespace

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

TEST(RunConfig, OverridesAndDefaults) {
    RunOverrides o;
    o.seed = 9;
    o.run_index = 3;
    o.steps = 10;
    const RunConfig rc = RunConfig::parse(kChain, "chain", o);
    EXPECT_EQ(rc.info.seed, 9u);
    EXPECT_EQ(rc.info.run_index, 3u);
    EXPECT_EQ(rc.info.steps, 10u);
    EXPECT_EQ(rc.window_steps, 64u);
    EXPECT_EQ(rc.done_every(), 32u);
    EXPECT_EQ(rc.members.size(), 4u);
    // The resolved document parses back to the same values.
    const RunConfig again = RunConfig::parse(rc.to_yaml(), "again");
    EXPECT_EQ(again.info.seed, 9u);
    EXPECT_EQ(again.info.steps, 10u);
}

TEST(RunConfig, DurationGivesStepsIncludingBothEnds) {
    const RunConfig rc = RunConfig::parse("run: {seed: 1, duration_s: 500, t0_s: -50}\ncomponents: {x: {type: y}}\n", "d");
    EXPECT_EQ(rc.info.steps, 50001u);
}

TEST(RunConfig, RejectsUnknownTopLevelAndEssentialNames) {
    EXPECT_THROW(RunConfig::parse("run: {seed: 1, steps: 1}\ncomponents: {x: {type: y}}\nextra: 1\n", "t"),
                 config::ConfigError);
    EXPECT_THROW(RunConfig::parse("run: {seed: 1, steps: 1, essential: [z]}\ncomponents: {x: {type: y}}\n", "t"),
                 config::ConfigError);
    EXPECT_THROW(RunConfig::parse("run: {seed: 1, steps: 1}\ncomponents: {clock: {type: y}}\n", "t"),
                 config::ConfigError);
}

TEST(RunConfig, ObserverNiceDefaultsTo19AndIsCheckedAgainst0To19) {
    EXPECT_EQ(RunConfig::parse("run: {seed: 1, steps: 1}\ncomponents: {x: {type: y}}\n", "t").observer_nice, 19);
    EXPECT_EQ(RunConfig::parse("run: {seed: 1, steps: 1, observer_nice: 0}\ncomponents: {x: {type: y}}\n", "t")
                  .observer_nice,
              0);
    for (const char* bad : {"20", "-1", "high"}) {
        try {
            RunConfig::parse(std::string("run: {seed: 1, steps: 1, observer_nice: ") + bad +
                                 "}\ncomponents: {x: {type: y}}\n",
                             "t");
            ADD_FAILURE() << "observer_nice " << bad << " accepted";
        } catch (const config::ConfigError& e) {
            EXPECT_NE(std::string(e.what()).find("observer_nice"), std::string::npos) << e.what();
        }
    }
}

TEST(Shm, OnlyFastDdsNamesAreCandidates) {
    EXPECT_TRUE(is_fastdds_shm_name("fastrtps_0a1b2c3d4e5f6a7b"));
    EXPECT_TRUE(is_fastdds_shm_name("sem.fastrtps_port7413_mutex"));
    EXPECT_TRUE(is_fastdds_shm_name("fast_datasharing_01.0f.aa.bb"));
    EXPECT_FALSE(is_fastdds_shm_name("postgres_shm"));
    EXPECT_FALSE(is_fastdds_shm_name("sem.other"));
}
