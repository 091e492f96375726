// DDS Security (dds/security, gdnav pki init, run.security / --security).
//  - a secure scenario-#2 run (composed layout: the clock and one process) gives bit-identical outputs to the plain
//    run; the distributed layout is refused with --security (Fast DDS 2.9.1 limitation, docs/deployment.md);
//  - a participant without a certificate is never matched with the run's endpoints and cannot change it (it writes
//    Tick `last` and RunControl ABORT all through the run), while in a plain run the same participant does match;
//  - a participant with a valid certificate cannot create a writer on a topic its permissions do not grant;
//  - an expired certificate, a certificate of another CA, permissions signed by another CA and a missing directory
//    each stop `gdnav run` before anything starts, with one error line naming the file.
#include <gtest/gtest.h>
#include <unistd.h>

#include <chrono>
#include <fstream>
#include <thread>

#include <fastdds/dds/publisher/DataWriter.hpp>
#include <fastdds/dds/subscriber/DataReader.hpp>

#include "process_util.hpp"
#include "dds/dds_context.hpp"
#include "framework/lockstep.hpp"
#include "msgs/messages.hpp"
#include "framework/run_config.hpp"
#include "framework/topic_types.hpp"

using namespace gdnav::testing;
namespace msg = gdnav::msg;
namespace framework = gdnav::framework;
namespace fs = std::filesystem;
using namespace eprosima::fastdds::dds;

namespace {

constexpr int kDomain = 151;  // integration tests run one at a time (RUN_SERIAL)
constexpr const char* kSteps = "3000";
const char* kRecord = "AirDataEstimate,AttitudeEstimate,PositionEstimate,ControlCommands,ImuSample";

fs::path profile() { return framework::config_dir() / "dds" / "gdnav_profiles.xml"; }

// One PKI for the suite (gdnav pki init takes about a second per dozen identities).
const fs::path& pki() {
    static const fs::path dir = [] {
        const fs::path d = temp_dir("pki") / "pki";
        const Result r = run({GDNAV_GDNAV_EXE, "pki", "init", d.string(), "--scenario", "paper2"}, 120.0);
        EXPECT_EQ(r.exit_code, 0) << r.output;
        return d;
    }();
    return dir;
}

std::vector<std::string> run_argv(const fs::path& out, const std::string& security,
                                  const std::string& layout = "composed") {
    std::vector<std::string> a{GDNAV_GDNAV_EXE, "run",     "--scenario", "paper2",      "--layout",
                               layout,          "--steps", kSteps,       "--domain",    std::to_string(kDomain),
                               "--record",      kRecord,   "--out",      out.string()};
    if (!security.empty()) {
        a.push_back("--security");
        a.push_back(security);
    }
    return a;
}

// An outsider without a certificate on the run's domain, for the whole run: reads StepDone and ImuSample, and (when
// `attack`) writes Tick with `last` set and RunControl ABORT every 20 ms. Returns the largest matched count seen.
struct Outsider {
    int max_matched{0};
    std::uint64_t written{0};
};
Outsider outsider_during(pid_t launcher, bool attack, int* code) {
    framework::register_gdnav_topics();
    gdnav::dds::DdsContext dds(kDomain, profile(), "gdnav.test.outsider");
    // Reads topics it does not write (a reader of its own Tick writer would match it inside its own participant).
    DataReader* done_r = dds.reader(gdnav::topics::kStepDone, msg::message_ops<gdnav::msg::StepDone>(),
                                    gdnav::dds::kControlReaderProfile);
    DataReader* imu_r =
        dds.reader(gdnav::topics::kImu, *framework::find_topic(gdnav::topics::kImu), gdnav::dds::kDataReaderProfile);
    DataWriter* tick_w =
        dds.writer(gdnav::topics::kTick, msg::message_ops<gdnav::msg::Tick>(), gdnav::dds::kControlWriterProfile);
    DataWriter* ctl_w = dds.writer(gdnav::topics::kRunControl, msg::message_ops<gdnav::msg::RunControl>(),
                                   gdnav::dds::kLatchedWriterProfile);
    Outsider o;
    const auto deadline = std::chrono::steady_clock::now() + std::chrono::seconds(150);
    while ((*code = wait_for(launcher, 0.0)) == -1 && std::chrono::steady_clock::now() < deadline) {
        SubscriptionMatchedStatus sm;
        PublicationMatchedStatus pm;
        for (DataReader* r : {done_r, imu_r}) {
            r->get_subscription_matched_status(sm);
            o.max_matched = std::max(o.max_matched, sm.current_count);
        }
        for (DataWriter* w : {tick_w, ctl_w}) {
            w->get_publication_matched_status(pm);
            o.max_matched = std::max(o.max_matched, pm.current_count);
        }
        if (attack) {
            gdnav::msg::Tick t;
            t.stamp().run_id(0);
            t.stamp().step(10);
            t.last(true);
            tick_w->write(&t);
            gdnav::msg::RunControl c;
            c.run_id(0);
            c.command(gdnav::msg::RUN_ABORT);
            c.reason("outsider");
            ctl_w->write(&c);
            o.written += 2;
        }
        std::this_thread::sleep_for(std::chrono::milliseconds(20));
    }
    if (*code == -1) *code = wait_for(launcher, 10.0);
    return o;
}

}  // namespace

TEST(Security, SecureRunIsBitIdenticalAndAnOutsiderWithoutCertificateIsNeverMatched) {
    ASSERT_TRUE(fs::is_regular_file(pki() / "permissions.p7s"));
    const auto plain_out = temp_dir("plain");
    const pid_t plain = start(run_argv(plain_out, ""), plain_out.string() + ".log");
    int plain_code = -1;
    const Outsider seen_plain = outsider_during(plain, false, &plain_code);
    ASSERT_EQ(plain_code, 0) << read_file(plain_out.string() + ".log");

    const auto secure_out = temp_dir("secure");
    const auto t0 = std::chrono::steady_clock::now();
    const pid_t secure = start(run_argv(secure_out, pki().string()), secure_out.string() + ".log");
    int secure_code = -1;
    const Outsider seen_secure = outsider_during(secure, true, &secure_code);
    const double wall = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
    const std::string log = read_file(secure_out.string() + ".log");
    std::printf("plain run: outsider matched up to %d endpoints; secure run (%.1f s wall, %s steps): outsider "
                "matched up to %d endpoints after writing %llu Tick/ABORT samples\n",
                seen_plain.max_matched, wall, kSteps, seen_secure.max_matched,
                static_cast<unsigned long long>(seen_secure.written));
    ASSERT_EQ(secure_code, 0) << log;
    EXPECT_NE(log.find("DDS Security on"), std::string::npos) << log;
    EXPECT_GT(seen_plain.max_matched, 0) << "the outsider should match a plain run (else this test proves nothing)";
    EXPECT_EQ(seen_secure.max_matched, 0);
    EXPECT_GT(seen_secure.written, 0u);

    const auto plain_d = read_digests(plain_out);
    const auto secure_d = read_digests(secure_out);
    EXPECT_EQ(plain_d.size(), 5u);
    EXPECT_EQ(plain_d, secure_d);
}

TEST(Security, ACertifiedParticipantCannotWriteATopicItsPermissionsDoNotGrant) {
    framework::register_gdnav_topics();
    gdnav::dds::DdsContext dds(kDomain, profile(), "gdnav.test.gnss", pki(), "sensors_gnss");
    // Granted: its own output.
    EXPECT_NO_THROW(
        dds.writer(gdnav::topics::kGnss, *framework::find_topic(gdnav::topics::kGnss), gdnav::dds::kDataWriterProfile));
    // Not granted: the clock's Tick, the physics' Truth, another sensor's samples.
    EXPECT_THROW(
        dds.writer(gdnav::topics::kTick, msg::message_ops<gdnav::msg::Tick>(), gdnav::dds::kControlWriterProfile),
        std::runtime_error);
    EXPECT_THROW(dds.writer(gdnav::topics::kTruth, *framework::find_topic(gdnav::topics::kTruth),
                            gdnav::dds::kDataWriterProfile),
                 std::runtime_error);
    EXPECT_THROW(
        dds.writer(gdnav::topics::kImu, *framework::find_topic(gdnav::topics::kImu), gdnav::dds::kDataWriterProfile),
        std::runtime_error);
    // Reading is granted for every topic.
    EXPECT_NO_THROW(
        dds.reader(gdnav::topics::kTick, msg::message_ops<gdnav::msg::Tick>(), gdnav::dds::kControlReaderProfile));
}

namespace {

fs::path copy_pki(const std::string& tag) {
    const fs::path d = temp_dir(tag) / "pki";
    fs::copy(pki(), d, fs::copy_options::recursive);
    return d;
}

// `gdnav run --security dir` must fail before anything starts, with one error line containing `what` and `file`.
void expect_refused(const fs::path& dir, const std::string& file, const std::string& what) {
    const auto out = temp_dir("refused");
    const Result r = run(run_argv(out, dir.string()), 60.0);
    EXPECT_EQ(r.exit_code, framework::kExitConfig) << r.output;
    std::size_t errors = 0, pos = 0;
    while ((pos = r.output.find("] error: ", pos)) != std::string::npos) ++errors, ++pos;
    EXPECT_EQ(errors, 1u) << r.output;
    EXPECT_NE(r.output.find(file), std::string::npos) << r.output;
    EXPECT_NE(r.output.find(what), std::string::npos) << r.output;
    EXPECT_FALSE(fs::exists(out / "processes.yaml")) << "processes were started: " << r.output;
    std::printf("refused as expected: %s", r.output.substr(r.output.find("] error: ") + 2).c_str());
}

// A certificate for CN=NAME,O=gdnav signed by the suite's CA, valid from 2020-01-01 to 2020-01-02 (openssl ca).
void make_expired_certificate(const fs::path& dir, const std::string& name) {
    const fs::path ca = dir / "expired-ca";
    fs::create_directories(ca);
    std::ofstream(ca / "index.txt").close();
    std::ofstream(ca / "serial") << "1000\n";
    std::ofstream(ca / "ca.cnf") << "[ca]\ndefault_ca=d\n[d]\ndatabase=" << (ca / "index.txt").string()
                                 << "\nnew_certs_dir=" << ca.string() << "\nserial=" << (ca / "serial").string()
                                 << "\npolicy=p\ndefault_md=sha256\n[p]\ncommonName=supplied\norganizationName=supplied\n";
    const std::string key = (dir / "identities" / (name + ".key")).string();
    const std::string csr = (ca / "x.csr").string();
    Result r = run({"/usr/bin/openssl", "req", "-new", "-key", key, "-subj", "/CN=" + name + "/O=gdnav", "-out", csr});
    ASSERT_EQ(r.exit_code, 0) << r.output;
    r = run({"/usr/bin/openssl", "ca", "-batch", "-config", (ca / "ca.cnf").string(), "-cert", (dir / "ca.pem").string(),
             "-keyfile", (dir / "ca.key").string(), "-in", csr, "-out",
             (dir / "identities" / (name + ".pem")).string(), "-startdate", "20200101000000Z", "-enddate",
             "20200102000000Z", "-notext", "-preserveDN"});
    ASSERT_EQ(r.exit_code, 0) << r.output;
}

}  // namespace

TEST(Security, BadMaterialIsOneClearErrorAndNothingStarts) {
    const fs::path other = temp_dir("other-pki") / "pki";
    ASSERT_EQ(run({GDNAV_GDNAV_EXE, "pki", "init", other.string(), "--scenario", "paper2"}, 120.0).exit_code, 0);

    const fs::path expired = copy_pki("expired");
    make_expired_certificate(expired, "composed");
    expect_refused(expired, "identities/composed.pem", "certificate has expired");

    const fs::path foreign = copy_pki("foreign");
    for (const char* ext : {".pem", ".key"})
        fs::copy_file(other / "identities" / (std::string("clock") + ext),
                      foreign / "identities" / (std::string("clock") + ext), fs::copy_options::overwrite_existing);
    expect_refused(foreign, "identities/clock.pem", "certificate signature failure");

    const fs::path resigned = copy_pki("resigned");
    fs::copy_file(other / "permissions.p7s", resigned / "permissions.p7s", fs::copy_options::overwrite_existing);
    expect_refused(resigned, "permissions.p7s", "signature does not verify");

    expect_refused(temp_dir("missing") / "nowhere", "nowhere", "not a directory");

    // Valid material, but the distributed layout: refused up front rather than timing out on unmatched endpoints.
    const auto dist_out = temp_dir("distributed");
    const Result dist = run(run_argv(dist_out, pki().string(), "distributed"), 60.0);
    EXPECT_EQ(dist.exit_code, framework::kExitConfig) << dist.output;
    EXPECT_NE(dist.output.find("not with --layout distributed"), std::string::npos) << dist.output;
    EXPECT_FALSE(fs::exists(dist_out / "processes.yaml"));

    // And pki init refuses to overwrite a CA.
    const Result again = run({GDNAV_GDNAV_EXE, "pki", "init", other.string(), "--scenario", "paper2"}, 60.0);
    EXPECT_NE(again.exit_code, 0);
    EXPECT_NE(again.output.find("already holds a CA"), std::string::npos) << again.output;
}
