// Scheduled faults (runtime/faults): parsing and validation errors, and what each kind delivers to a consumer.
#include <gtest/gtest.h>

#include <unistd.h>

#include <cmath>
#include <filesystem>
#include <fstream>

#include "framework/faults/fault_schedule.hpp"
#include "framework/faults/input_faults.hpp"
#include "msgs/messages.hpp"
#include "framework/run_config.hpp"
#include "framework/topic_types.hpp"

using namespace gdnav;
using framework::faults::FaultSchedule;
using framework::faults::InputFaults;
using framework::faults::Kind;
using framework::faults::MemberPorts;

namespace {

framework::RunInfo run_info() {
    framework::RunInfo r;
    r.seed = 7;
    r.run_index = 3;
    r.steps = 1000;
    r.dt_s = 0.01;
    r.t0_s = -1.0;  // step k at t = -1 + 0.01 k
    return r;
}

FaultSchedule parse(const std::string& yaml) {
    return FaultSchedule::parse(config::Config::parse(yaml, "f.yaml"), run_info());
}

std::string error_of(const std::string& yaml, const std::map<std::string, MemberPorts>& members = {}) {
    try {
        const FaultSchedule s = parse(yaml);
        if (!members.empty()) s.validate(members, "f.yaml");
    } catch (const config::ConfigError& e) {
        return e.what();
    }
    return "";
}

const std::map<std::string, MemberPorts> kMembers{
    {"sensors_air", {{"gdnav/AirSample"}, false}},
    {"sensors_gnss", {{"gdnav/GnssSample"}, false}},
    {"two", {{"gdnav/AirSample", "gdnav/AtmSample"}, false}},
    {"ext", {{}, true}},
};

msg::AirSample air(std::uint64_t k, double tas) {
    msg::AirSample a;
    a.stamp().run_id(3);
    a.stamp().step(k);
    a.stamp().t_s(run_info().time_of(k));
    a.tas_mps(tas);
    a.aoa_rad(0.05);
    return a;
}

struct Consumer {
    FaultSchedule schedule;
    InputFaults faults;
    explicit Consumer(const std::string& yaml)
        : schedule(parse(yaml)),
          faults(schedule, "gdnav/AirSample", {"sensors_air"}, msg::message_ops<msg::AirSample>(), run_info()) {}
    // What the consumer sees at step k when the producer published tas = k.
    const msg::AirSample* at(std::uint64_t k) {
        static msg::AirSample published;
        published = air(k, static_cast<double>(k));
        return static_cast<const msg::AirSample*>(faults.apply(k, &published).data);
    }
};

}  // namespace

TEST(FaultSchedule, TimesBecomeStepsAndKillsEndAtTheirRestart) {
    framework::register_gdnav_topics();
    const FaultSchedule s = parse(
        "faults:\n"
        "  - {at_s: 0, until_s: 0.5, target: sensors_air, kind: drop}\n"
        "  - {at_s: 1.0, target: nav_att, kind: kill}\n"
        "  - {at_s: 2.0, target: nav_att, kind: restart}\n");
    ASSERT_EQ(s.faults().size(), 3u);
    EXPECT_EQ(s.faults()[0].from_step, 100u);  // t = 0 is step 100
    EXPECT_EQ(s.faults()[0].until_step, 150u);
    EXPECT_TRUE(s.killed("nav_att", 200));
    EXPECT_TRUE(s.killed("nav_att", 299));
    EXPECT_FALSE(s.killed("nav_att", 300));
    EXPECT_TRUE(s.restarts_at("nav_att", 300));
    EXPECT_EQ(s.alive_again("nav_att", 250), 300u);
    // The schedule survives its trip through CONFIGURE.
    const FaultSchedule back = FaultSchedule::from_yaml(s.to_yaml(), run_info());
    EXPECT_EQ(back.to_yaml(), s.to_yaml());
    EXPECT_TRUE(back.killed("nav_att", 250));
}

TEST(FaultSchedule, BadEntriesGiveOneLineNamingTheKey) {
    framework::register_gdnav_topics();
    const std::vector<std::pair<std::string, std::string>> cases{
        {"faults: [{at_s: 1, target: sensors_air, kind: melt}]", "key 'faults[0].kind'"},
        {"faults: [{at_s: .nan, target: sensors_air, kind: drop}]", "key 'faults[0].at_s'"},
        {"faults: [{at_s: 50, target: sensors_air, kind: drop}]", "key 'faults[0].at_s'"},  // after the run's end
        {"faults: [{at_s: 2, until_s: 1, target: sensors_air, kind: drop}]", "key 'faults[0].until_s'"},
        {"faults: [{at_s: 1, target: sensors_air, kind: drop, colour: red}]", "key 'faults[0].colour': unknown key"},
        {"faults: [{at_s: 1, target: sensors_air, kind: loss, p: 1.5}]", "key 'faults[0].p'"},
        {"faults: [{at_s: 1, target: sensors_air, kind: delay, steps: 0}]", "key 'faults[0].steps'"},
        {"faults: [{at_s: 1, target: sensors_air, kind: noise, fields: {tas_mps: -1}}]", "key 'faults[0].fields.tas_mps'"},
        {"faults: [{at_s: 1, target: sensors_air, kind: bias, fields: {tas_mps: .inf}}]", "key 'faults[0].fields.tas_mps'"},
        {"faults: [{at_s: 1, target: nav_att, kind: restart}]", "no kill of 'nav_att'"},
        {"faults: [{at_s: 1, target: a, kind: kill}, {at_s: 2, target: a, kind: kill}]", "'a' is already killed"},
        {"faults: [{at_s: 1, target: nobody, kind: drop}]", "key 'faults[0].target': 'nobody' is not a member"},
        {"faults: [{at_s: 1, target: sensors_air, topic: gdnav/Truth, kind: drop}]", "not an output of 'sensors_air'"},
        {"faults: [{at_s: 1, target: sensors_air, kind: bias, fields: {speed: 1}}]", "key 'faults[0].fields.speed'"},
        {"faults: [{at_s: 1, target: sensors_gnss, kind: bias, fields: {v_n_mps: [1, 2]}}]", "give 1 value or 3"},
        {"faults: [{at_s: 1, target: two, kind: bias, fields: {tas_mps: 1}}]", "key 'faults[0].topic': required"},
        {"faults: [{at_s: 1, until_s: 2, target: ext, kind: kill}]", "external member"},
    };
    for (const auto& [yaml, expected] : cases) {
        const std::string e = error_of(yaml, kMembers);
        EXPECT_NE(e.find(expected), std::string::npos) << yaml << "\n  gave: " << e;
        EXPECT_NE(e.find("f.yaml"), std::string::npos) << e;
        EXPECT_EQ(e.find('\n'), std::string::npos) << e;
    }
    EXPECT_EQ(error_of("faults: [{at_s: 1, until_s: 2, target: sensors_gnss, kind: bias, fields: {v_n_mps: [1, 2, 3]}}]",
                       kMembers),
              "");
}

TEST(InputFaults, EachKindDeliversWhatItsDocumentationSays) {
    framework::register_gdnav_topics();
    // t = -1 + 0.01 k: at_s 0 is step 100.
    {
        Consumer c("faults: [{at_s: 0, until_s: 0.05, target: sensors_air, kind: drop}]");
        EXPECT_NE(c.at(99), nullptr);
        EXPECT_EQ(c.at(100), nullptr);
        EXPECT_EQ(c.at(104), nullptr);
        ASSERT_NE(c.at(105), nullptr);
        EXPECT_EQ(c.at(105)->tas_mps(), 105.0);
    }
    {
        Consumer c("faults: [{at_s: 0, until_s: 0.05, target: sensors_air, kind: freeze}]");
        for (std::uint64_t k = 90; k < 100; ++k) (void)c.at(k);
        const auto* f = c.at(102);
        ASSERT_NE(f, nullptr);
        EXPECT_EQ(f->tas_mps(), 99.0);        // the last sample before the fault
        EXPECT_EQ(f->stamp().step(), 102u);   // re-stamped: a stuck sensor, not a late message
        EXPECT_EQ(c.at(105)->tas_mps(), 105.0);
    }
    {
        Consumer c("faults: [{at_s: 0, target: sensors_air, kind: bias, fields: {tas_mps: 2.5}}]");
        EXPECT_EQ(c.at(99)->tas_mps(), 99.0);
        EXPECT_EQ(c.at(100)->tas_mps(), 102.5);
        EXPECT_EQ(c.at(100)->aoa_rad(), 0.05);  // other fields untouched
    }
    {
        Consumer c("faults: [{at_s: 0, target: sensors_air, kind: delay, steps: 3}]");
        for (std::uint64_t k = 90; k < 100; ++k) (void)c.at(k);
        const auto* d = c.at(100);
        ASSERT_NE(d, nullptr);
        EXPECT_EQ(d->tas_mps(), 97.0);
        EXPECT_EQ(d->stamp().step(), 97u);  // a late message keeps its stamp
    }
    {
        Consumer c("faults: [{at_s: 0, until_s: 0.01, target: sensors_air, kind: nan, fields: [aoa_rad]}]");
        EXPECT_TRUE(std::isnan(c.at(100)->aoa_rad()));
        EXPECT_EQ(c.at(100)->tas_mps(), 100.0);
        EXPECT_FALSE(std::isnan(c.at(101)->aoa_rad()));
    }
    {
        Consumer c("faults: [{at_s: 0, until_s: 0.1, target: sensors_air, kind: kill}]");
        msg::AirSample p = air(100, 1.0);
        const auto d = c.faults.apply(100, &p);
        EXPECT_EQ(d.data, nullptr);
        EXPECT_TRUE(d.lost);
        EXPECT_TRUE(c.faults.producer_killed(109));
        EXPECT_FALSE(c.faults.producer_killed(110));
    }
}

TEST(InputFaults, LossAndNoiseAreTheSameForEveryConsumerAndFollowTheirLaw) {
    framework::register_gdnav_topics();
    const std::string yaml =
        "faults:\n"
        "  - {at_s: 0, until_s: 40, target: sensors_air, kind: loss, p: 0.3}\n"
        "  - {at_s: 0, until_s: 40, target: sensors_air, kind: noise, fields: {tas_mps: 2.0}}\n";
    Consumer a(yaml), b(yaml);
    int lost = 0, n = 0;
    double sum = 0.0, sum2 = 0.0;
    for (std::uint64_t k = 100; k < 4100; ++k) {
        const auto* x = a.at(k);
        const double xa = x ? x->tas_mps() : NAN;
        const auto* y = b.at(k);
        ASSERT_EQ(x == nullptr, y == nullptr) << k;
        if (!x) {
            ++lost;
            continue;
        }
        EXPECT_EQ(xa, y->tas_mps()) << k;  // bit for bit, whoever consumes
        const double e = xa - static_cast<double>(k);
        sum += e;
        sum2 += e * e;
        ++n;
    }
    // 4000 Bernoulli(0.3) draws: 1200 +- 29 (1 sigma); noise N(0, 2^2) over ~2800 samples: mean 0 +- 0.04.
    EXPECT_NEAR(lost, 1200, 120);
    const double mean = sum / n;
    const double sd = std::sqrt(sum2 / n - mean * mean);
    EXPECT_NEAR(mean, 0.0, 0.15);
    EXPECT_NEAR(sd, 2.0, 0.1);
    std::printf("loss p=0.3: %d of 4000 dropped; noise sigma 2: mean %.3f, sd %.3f over %d samples\n", lost, mean, sd, n);
    // Another run of the batch draws its own losses.
    framework::RunInfo other = run_info();
    other.run_index = 4;
    InputFaults c(a.schedule, "gdnav/AirSample", {"sensors_air"}, msg::message_ops<msg::AirSample>(), other);
    Consumer d(yaml);
    int differ = 0;
    for (std::uint64_t k = 100; k < 1100; ++k) {
        msg::AirSample p = air(k, 0.0);
        const bool lost_here = d.faults.apply(k, &p).data == nullptr;
        const bool lost_there = c.apply(k, &p).data == nullptr;
        differ += lost_here != lost_there;
    }
    EXPECT_GT(differ, 200) << "run index 4 must not repeat run 3's losses (expected ~420 of 1000 steps differ)";
}

TEST(FaultSchedule, AFaultsFileReplacesTheListAndNamesItselfInErrors) {
    const std::string run_yaml =
        "run: {seed: 1, steps: 100}\n"
        "components: {a: {type: chain_plant}}\n"
        "faults: [{at_s: 0.5, target: a, kind: drop}]\n";
    const auto file = std::filesystem::temp_directory_path() / ("gdnav_faults_" + std::to_string(::getpid()) + ".yaml");
    {
        std::ofstream f(file);
        f << "faults: [{at_s: 0.2, until_s: 0.3, target: a, kind: freeze}]\n";
    }
    framework::RunOverrides o;
    o.faults_file = file;
    const auto rc = framework::RunConfig::parse(run_yaml, "r.yaml", o);
    ASSERT_EQ(rc.faults.faults().size(), 1u);
    EXPECT_EQ(rc.faults.faults()[0].kind, Kind::Freeze);
    EXPECT_EQ(rc.faults.faults()[0].from_step, 20u);
    {
        std::ofstream f(file);
        f << "faults: [{at_s: 0.2, target: a, kind: melt}]\n";
    }
    try {
        (void)framework::RunConfig::parse(run_yaml, "r.yaml", o);
        ADD_FAILURE() << "a bad kind in the faults file was accepted";
    } catch (const config::ConfigError& e) {
        EXPECT_NE(std::string(e.what()).find(file.string() + ": key 'faults[0].kind'"), std::string::npos) << e.what();
    }
    std::filesystem::remove(file);
}
