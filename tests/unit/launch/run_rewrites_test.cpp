#include "launch/run_rewrites.hpp"

#include <algorithm>

#include <gtest/gtest.h>

#include "config/config.hpp"
#include "framework/topic_types.hpp"
#include "temp_dir.hpp"
#include "paper_scenarios.hpp"

namespace gdnav::launch {
namespace {

using framework::RunConfig;

class RunRewritesTest : public ::testing::Test {
protected:
    void SetUp() override {
        framework::register_gdnav_topics();
        scenario::register_paper_scenarios();
    }

    RunConfig base() const {
        framework::RunOverrides o;
        o.out_dir = dir_.path().string();
        return RunConfig::load(framework::resolve_scenario("default"), o);
    }

    // The one-line error of applying `rw` to the default scenario ("" when it is accepted).
    std::string error_of(const RunRewrites& rw) const {
        try {
            (void)apply_run_rewrites(base(), rw, reg_);
        } catch (const config::ConfigError& e) {
            return e.what();
        }
        return "";
    }

    static const framework::MemberSpec* member(const RunConfig& rc, const std::string& name) {
        const auto it = std::find_if(rc.members.begin(), rc.members.end(),
                                     [&](const framework::MemberSpec& m) { return m.name == name; });
        return it == rc.members.end() ? nullptr : &*it;
    }

    test::TempDir dir_;
    framework::ComponentRegistry reg_;  // the record rewrite needs no component type
};

TEST_F(RunRewritesTest, NoRewriteKeepsTheMembers) {
    const RunConfig rc = base();
    const RunConfig out = apply_run_rewrites(rc, RunRewrites{}, reg_);
    ASSERT_EQ(out.members.size(), rc.members.size());
    for (std::size_t i = 0; i < rc.members.size(); ++i) EXPECT_EQ(out.members[i].name, rc.members[i].name);
    EXPECT_EQ(out.info.seed, rc.info.seed);
    EXPECT_EQ(out.info.steps, rc.info.steps);
}

TEST_F(RunRewritesTest, RecordDefaultAddsARecorderOfTheFiveSensorTopics) {
    RunRewrites rw;
    rw.record = {"default"};
    const RunConfig rc = base();
    const RunConfig out = apply_run_rewrites(rc, rw, reg_);
    EXPECT_EQ(out.members.size(), rc.members.size() + 1);
    const framework::MemberSpec* r = member(out, "recorder");
    ASSERT_NE(r, nullptr);
    EXPECT_EQ(r->type, "recorder");
    EXPECT_EQ(r->cfg.node()["topics"].as<std::vector<std::string>>(),
              (std::vector<std::string>{"gdnav/ImuSample", "gdnav/MagSample", "gdnav/AirSample", "gdnav/AtmSample",
                                        "gdnav/GnssSample"}));
    EXPECT_FALSE(r->cfg.node()["viewer"]);
}

TEST_F(RunRewritesTest, RecordShortNamesOnceAndTheViewerChannels) {
    RunRewrites rw;
    rw.record = {"ImuSample", "gdnav/ImuSample", "viewer"};
    const RunConfig out = apply_run_rewrites(base(), rw, reg_);
    const framework::MemberSpec* r = member(out, "recorder");
    ASSERT_NE(r, nullptr);
    EXPECT_EQ(r->cfg.node()["topics"].as<std::vector<std::string>>(), (std::vector<std::string>{"gdnav/ImuSample"}));
    EXPECT_TRUE(r->cfg.node()["viewer"].as<bool>());
}

TEST_F(RunRewritesTest, BadOptionsGiveOneLineNamingTheOption) {
    RunRewrites unknown;
    unknown.record = {"NoSuchTopic"};
    EXPECT_EQ(error_of(unknown).rfind("config error: --record: unknown topic 'NoSuchTopic' (known: ", 0), 0u)
        << error_of(unknown);
    RunRewrites all_and_more;
    all_and_more.record = {"all", "ImuSample"};
    EXPECT_EQ(error_of(all_and_more), "config error: --record: 'all' must be given alone");
    RunRewrites topics_alone;
    topics_alone.replay_topics = {"ImuSample"};
    EXPECT_EQ(error_of(topics_alone), "config error: --topics: needs --replay RUN_DIR");
}

}  // namespace
}  // namespace gdnav::launch
