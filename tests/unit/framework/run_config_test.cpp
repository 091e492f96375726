// Run-config parsing: overrides, defaults, duration, and the names it rejects.
#include <gtest/gtest.h>

#include "framework/run_config.hpp"
#include "probe_chain.hpp"

using namespace gdnav;
using namespace gdnav::framework;
using namespace gdnav::framework::test;

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
