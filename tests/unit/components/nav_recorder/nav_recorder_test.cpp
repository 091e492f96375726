// nav_recorder against a synthetic truth and a deliberately perturbed estimate with known errors: online metrics,
// metrics.yaml, the HDF5 layout, and the files a killed (SIGKILL) or interrupted run leaves.
#include <gtest/gtest.h>
#include <hdf5.h>
#include <signal.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cmath>
#include <filesystem>

#include "metrics/run_record.hpp"
#include "nav_recorder.hpp"
#include "framework/direct_executor.hpp"
#include "msgs/messages.hpp"
#include "framework/run_config.hpp"

using namespace gdnav;
namespace fs = std::filesystem;

namespace {

constexpr double kLat0 = 0.7853981633974483;  // 45 deg
constexpr double kH = 1000.0;
constexpr double kSpeed = 30.0;

// Straight and level northbound flight at 30 m/s, pitch 0.05 rad.
class FakeTruth final : public framework::Component {
public:
    using Component::Component;
    void configure(const config::Config&, const framework::RunInfo& run, rnd::Stream&) override { t0_ = run.t0_s; }
    void step(const framework::StepContext& ctx) override {
        auto& t = out_.value();
        const earth::Radii r = earth::radii(kLat0);
        t.lat_rad(kLat0 + kSpeed * (ctx.t_s - t0_) / (r.m_m + kH));
        t.lon_rad(-1.5707963267948966);
        t.h_m(kH);
        t.v_n_mps({kSpeed, 0.0, 0.0});
        const math::Quat q = math::quat_from_euler({0.0, 0.05, 0.0});
        t.q_nb({q.w(), q.x(), q.y(), q.z()});
        t.euler_rad({0.0, 0.05, 0.0});
        t.tas_mps(kSpeed);
        t.aoa_rad(0.05);
        t.aos_rad(0.0);
        t.dT_K(2.0);
    }

private:
    framework::Output<msg::Truth> out_{*this, topics::kTruth};
    double t0_{0.0};
};

// The truth with known errors: TAS +0.5 m/s, AOA +0.01, AOS -0.02 rad, dT +0.3 K; attitude rotated 0.01 rad about
// the NED down axis (a pure yaw error); 100 m north; h +10 m; v_N +1, v_E -0.5 m/s.
class PerturbedEstimate final : public framework::Component {
public:
    using Component::Component;
    void configure(const config::Config&, const framework::RunInfo&, rnd::Stream&) override {}
    void step(const framework::StepContext&) override {
        const auto& t = truth_.get();
        auto& a = air_.value();
        a.tas_mps(t.tas_mps() + 0.5);
        a.aoa_rad(t.aoa_rad() + 0.01);
        a.aos_rad(t.aos_rad() - 0.02);
        a.dT_K(t.dT_K() + 0.3);
        const auto& qt = t.q_nb();
        const math::Quat q = math::quat_from_rotv({0.0, 0.0, 0.01}) * math::Quat(qt[0], qt[1], qt[2], qt[3]);
        att_.value().q_nb({q.w(), q.x(), q.y(), q.z()});
        auto& p = pos_.value();
        p.lat_rad(t.lat_rad() + 100.0 / (earth::radii(kLat0).m_m + kH));
        p.lon_rad(t.lon_rad());
        p.h_m(t.h_m() + 10.0);
        p.v_n_mps({t.v_n_mps()[0] + 1.0, t.v_n_mps()[1] - 0.5, t.v_n_mps()[2]});
    }

private:
    framework::Input<msg::Truth> truth_{*this, topics::kTruth};
    framework::Output<msg::AirDataEstimate> air_{*this, topics::kAirData};
    framework::Output<msg::AttitudeEstimate> att_{*this, topics::kAttitude};
    framework::Output<msg::PositionEstimate> pos_{*this, topics::kPosition};
};

framework::ComponentRegistry registry() {
    framework::ComponentRegistry reg;
    reg.add("fake_truth", "", [](const std::string& n) { return std::make_unique<FakeTruth>(n); });
    reg.add("perturbed", "", [](const std::string& n) { return std::make_unique<PerturbedEstimate>(n); });
    nav_recorder::register_nav_recorder(reg);
    return reg;
}

fs::path fresh_dir(const std::string& tag) {
    const fs::path d = fs::temp_directory_path() / ("gdnav_nav_recorder_" + tag + "_" + std::to_string(getpid()));
    fs::remove_all(d);
    return d;
}

// t in [-1, 10] s at 100 Hz (1101 steps), t_GNSS = 5 s, 10 Hz rows, flushes every 20 rows.
framework::RunConfig run_config(const fs::path& out) {
    const std::string yaml = "run: {seed: 3, run_index: 9, t0_s: -1.0, steps: 1101, dt_s: 0.01, out_dir: '" +
                             out.string() +
                             "'}\n"
                             "components:\n"
                             "  truth: {type: fake_truth}\n"
                             "  est: {type: perturbed}\n"
                             "  rec: {type: nav_recorder, t_gnss_s: 5, decimation: 10, flush_rows: 20, "
                             "gnss_track: false}\n";
    return framework::RunConfig::parse(yaml, "test");
}

struct H5Info {
    std::int64_t complete{-1};
    hsize_t truth_rows{0};
    int error_fields{0};
    bool metrics{false};
    double last_hor{0.0};
};

H5Info read_h5(const fs::path& file) {
    H5Info info;
    const hid_t f = H5Fopen(file.c_str(), H5F_ACC_RDONLY, H5P_DEFAULT);
    if (f < 0) return info;
    const hid_t a = H5Aopen(f, "complete", H5P_DEFAULT);
    H5Aread(a, H5T_NATIVE_INT64, &info.complete);
    H5Aclose(a);
    const hid_t d = H5Dopen2(f, "truth", H5P_DEFAULT);
    const hid_t s = H5Dget_space(d);
    H5Sget_simple_extent_dims(s, &info.truth_rows, nullptr);
    H5Sclose(s);
    H5Dclose(d);
    const hid_t e = H5Dopen2(f, "error", H5P_DEFAULT);
    const hid_t et = H5Dget_type(e);
    info.error_fields = H5Tget_nmembers(et);
    // Read the last row's hor_m through a one-field memory type (the way any reader picks a column).
    const hid_t one = H5Tcreate(H5T_COMPOUND, sizeof(double));
    H5Tinsert(one, "hor_m", 0, H5T_NATIVE_DOUBLE);
    const hid_t es = H5Dget_space(e);
    hsize_t n = 0;
    H5Sget_simple_extent_dims(es, &n, nullptr);
    if (n > 0) {
        const hsize_t start[1] = {n - 1}, count[1] = {1};
        H5Sselect_hyperslab(es, H5S_SELECT_SET, start, nullptr, count, nullptr);
        const hid_t ms = H5Screate_simple(1, count, nullptr);
        H5Dread(e, one, ms, es, H5P_DEFAULT, &info.last_hor);
        H5Sclose(ms);
    }
    H5Sclose(es);
    H5Tclose(one);
    H5Tclose(et);
    H5Dclose(e);
    info.metrics = H5Lexists(f, "metrics", H5P_DEFAULT) > 0;
    H5Fclose(f);
    return info;
}

}  // namespace

TEST(NavRecorder, MetricsOfAPerturbedEstimate) {
    const fs::path out = fresh_dir("metrics");
    const auto reg = registry();
    const framework::RunConfig rc = run_config(out);
    framework::DirectExecutor ex(rc.build(reg), rc.info);
    ex.run();
    const metrics::RunRecord r = metrics::read_run_record(out / "metrics.yaml");
    using metrics::Signal;
    EXPECT_TRUE(r.complete);
    EXPECT_EQ(r.seed, 3u);
    EXPECT_EQ(r.run_index, 9u);
    EXPECT_EQ(r.steps, 1101u);
    EXPECT_EQ(r.samples, 1001u);  // t = 0 .. 10 s
    EXPECT_NEAR(r.t_end_s, 10.0, 1e-9);
    EXPECT_NEAR(r[Signal::yaw].mean, 0.01, 1e-12);
    EXPECT_NEAR(r[Signal::yaw].std, 0.0, 1e-9);
    EXPECT_NEAR(r[Signal::pitch].max, 0.0, 1e-12);
    EXPECT_NEAR(r[Signal::rot].final, 0.01, 1e-12);
    EXPECT_NEAR(r[Signal::tas].mean, 0.5, 1e-12);
    EXPECT_NEAR(r[Signal::aoa].mean, 0.01, 1e-12);
    EXPECT_NEAR(r[Signal::aos].max, -0.02, 1e-12);
    EXPECT_NEAR(r[Signal::dT].final, 0.3, 1e-12);
    EXPECT_NEAR(r[Signal::h].mean, 10.0, 1e-9);
    EXPECT_NEAR(r[Signal::vn].mean, 1.0, 1e-12);
    EXPECT_NEAR(r[Signal::ve].final, -0.5, 1e-12);
    EXPECT_NEAR(r[Signal::hor].final, 100.0, 1e-6);
    EXPECT_NEAR(r[Signal::along].final, 100.0, 1e-6);  // 100 m north of a northbound aircraft: ahead
    EXPECT_NEAR(r[Signal::cross].final, 0.0, 1e-6);
    EXPECT_NEAR(r.distance_m, 150.0, 1e-9);  // 30 m/s from t_GNSS = 5 s to 10 s
    EXPECT_NEAR(r.hor_pct, 100.0 * 100.0 / 150.0, 1e-6);

    const H5Info h = read_h5(out / "run.h5");
    EXPECT_EQ(h.complete, 1);
    EXPECT_EQ(h.truth_rows, 111u);  // k = 0, 10, ..., 1100
    EXPECT_EQ(h.error_fields, 18);
    EXPECT_TRUE(h.metrics);
    EXPECT_NEAR(h.last_hor, 100.0, 1e-6);
    fs::remove_all(out);
}

TEST(NavRecorder, InterruptedRunIsMarkedIncomplete) {
    const fs::path out = fresh_dir("interrupted");
    const auto reg = registry();
    const framework::RunConfig rc = run_config(out);
    framework::DirectExecutor ex(rc.build(reg), rc.info);
    for (std::uint64_t k = 0; k < 300; ++k) ex.step(k);
    ex.finish(false);  // what a stopped DDS host does
    EXPECT_FALSE(metrics::run_record_complete(out / "metrics.yaml"));
    const H5Info h = read_h5(out / "run.h5");
    EXPECT_EQ(h.complete, 0);
    EXPECT_EQ(h.truth_rows, 30u);  // everything recorded up to the stop is flushed
    EXPECT_TRUE(h.metrics);
    fs::remove_all(out);
}

TEST(NavRecorder, SigkilledRunLeavesAReadablePartialFile) {
    const fs::path out = fresh_dir("killed");
    const pid_t pid = fork();
    ASSERT_GE(pid, 0);
    if (pid == 0) {
        const auto reg = registry();
        const framework::RunConfig rc = run_config(out);
        framework::DirectExecutor ex(rc.build(reg), rc.info);
        for (std::uint64_t k = 0; k < 550; ++k) ex.step(k);  // flushes after rows 20 and 40 (steps 190, 390)
        raise(SIGKILL);
        _exit(0);
    }
    int st = 0;
    ASSERT_EQ(waitpid(pid, &st, 0), pid);
    ASSERT_TRUE(WIFSIGNALED(st));
    EXPECT_EQ(WTERMSIG(st), SIGKILL);
    const H5Info h = read_h5(out / "run.h5");
    EXPECT_EQ(h.complete, 0);
    EXPECT_EQ(h.truth_rows, 40u);  // the rows of the last flush; the 15 buffered since are lost
    EXPECT_EQ(h.error_fields, 18);
    EXPECT_FALSE(h.metrics);
    EXPECT_FALSE(metrics::run_record_complete(out / "metrics.yaml"));
    EXPECT_TRUE(fs::exists(out / "metrics.yaml"));  // the partial record of the last flush
    fs::remove_all(out);
}

TEST(NavRecorder, NoOutputDirectoryWritesNothing) {
    const auto reg = registry();
    framework::RunConfig rc = run_config("");
    rc.info.out_dir.clear();
    framework::DirectExecutor ex(rc.build(reg), rc.info);
    EXPECT_EQ(ex.run(), 1101u);
}
