// At scenario level: the position filter's GNSS integrity and the filters' input checks in
// full paper scenario-#2 runs (direct layout, 500 s), driven by scheduled faults (framework/faults,
// docs/faults.md) and read from the run's log, its ComponentStatus MODE messages and its run.h5 (nav_recorder):
//   * an outage that ends: GNSS kept (`never_lost`) but every sample dropped in [100.5, 300) s, seeds 1-3: lost at
//     101.51 s (last fix 100 s + the 1.5 s timeout), re-acquired at 304 s (5 consistent fixes at 1 Hz from 300 s),
//     the GNSS-denied flag in between, and the horizontal error back at the GNSS-aided level of the same run;
//   * spoofing: the fix moved 500 m north for 20 s with GNSS otherwise available: the chi-square gate rejects it, the
//     source is declared untrusted after 5 rejections, the spoofed fixes are refused for re-acquisition, the error
//     stays at the aided level plus a short dead reckoning, and GNSS is re-acquired 4 s after the spoofing ends;
//   * NaN samples on each sensor topic (IMU, magnetometer, air data, atmospheric, GNSS) at different times: the run
//     completes, each filter's end-of-run line counts exactly the faulted samples, the estimates stay finite and the
//     errors close to those of the fault-free run.
// Every figure is printed. About 9 runs of 55 001 steps: ~15 s on a quiet 2-core machine.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <limits>
#include <regex>
#include <string>
#include <vector>

#include "metrics/run_record.hpp"
#include "h5_column.hpp"
#include "math/rotation.hpp"
#include "process_util.hpp"

using namespace gdnav::testing;
namespace fs = std::filesystem;
using gdnav::metrics::Signal;

namespace {

using gdnav::math::kDeg;
constexpr double kDt = 0.01;  // scenario #2 step
const char* const kGnssKept = "components.sensors_gnss.never_lost=true";

struct RunOut {
    Result result;
    fs::path dir;
};

// One scenario-#2 run (paper2, direct layout) with --set overrides.
RunOut run_s2(const std::string& tag, int seed, const std::vector<std::string>& sets) {
    RunOut r;
    r.dir = temp_dir(tag);
    std::vector<std::string> argv{kExe, "run", "--scenario", "paper2", "--seed", std::to_string(seed), "--layout",
                                  "direct", "--out", r.dir.string()};
    for (const auto& s : sets) {
        argv.emplace_back("--set");
        argv.push_back(s);
    }
    r.result = run(argv, 180.0);
    return r;
}


struct Series {
    std::vector<double> t, v;
};
Series series(const fs::path& dir, const char* table, const char* name) {
    return {h5_column(dir / "run.h5", table, "t_s"), h5_column(dir / "run.h5", table, name)};
}

struct WindowStats {
    double max{-std::numeric_limits<double>::infinity()};
    double mean{0.0};
    int n{0};
    bool finite{true};
};
// Over the rows with lo <= t < hi.
WindowStats stats(const Series& s, double lo, double hi) {
    WindowStats w;
    double sum = 0.0;
    for (std::size_t i = 0; i < s.t.size() && i < s.v.size(); ++i) {
        if (s.t[i] < lo || s.t[i] >= hi) continue;
        if (!std::isfinite(s.v[i])) w.finite = false;
        w.max = std::max(w.max, s.v[i]);
        sum += s.v[i];
        ++w.n;
    }
    w.mean = w.n > 0 ? sum / w.n : std::numeric_limits<double>::quiet_NaN();
    return w;
}

// Times of the MODE messages of `member` that start with `what` ("[nav_pos] step K t=T s: what...").
std::vector<double> events(const std::string& log, const std::string& member, const std::string& what) {
    std::vector<double> t;
    const std::regex re("\\[" + member + "\\] step [0-9]+ t=([-0-9.]+) s: " + what);
    for (auto it = std::sregex_iterator(log.begin(), log.end(), re); it != std::sregex_iterator(); ++it)
        t.push_back(std::stod((*it)[1].str()));
    return t;
}

// The member's end-of-run log line (finish(): "[nav_pos] end of run: ..."), "" when absent.
std::string end_of_run(const std::string& log, const std::string& member) {
    const std::string key = "[" + member + "] end of run: ";
    const auto p = log.rfind(key);
    if (p == std::string::npos) return "";
    return log.substr(p, log.find('\n', p) - p);
}

// The count after `label` in an end-of-run line ("ImuSample 70, ..." -> 70); -1 when absent.
long count(const std::string& line, const std::string& label) {
    const auto p = line.find(label + " ");
    if (p == std::string::npos) return -1;
    return std::stol(line.substr(p + label.size() + 1));
}

// Steps of a fault window [at, until) at 100 Hz.
long steps(double at_s, double until_s) { return std::lround((until_s - at_s) / kDt); }

// 500 m north as a latitude offset: 500 / (M + h), M the WGS84 meridian radius of curvature at 45 deg (the paper
// scenarios' start latitude), h neglected (~1 km: 0.02 %). 7.85e-5 rad.
double lat_offset_rad(double north_m) {
    const double a = 6378137.0, e2 = 6.69437999014e-3, s = std::sin(45.0 * kDeg);
    const double m = a * (1.0 - e2) / std::pow(1.0 - e2 * s * s, 1.5);
    return north_m / m;
}

// The GNSS-denied flag (/estimate gnss_denied) is 0 before t_lost, 1 in [t_lost, t_back), 0 after (rows within one
// row period of a switch are not checked: the 10 Hz rows need not fall on the switching step).
void expect_denied_between(const fs::path& dir, double t_lost, double t_back) {
    const Series d = series(dir, "estimate", "gnss_denied");
    ASSERT_FALSE(d.t.empty()) << dir;
    int wrong = 0, checked = 0;
    for (std::size_t i = 0; i < d.t.size(); ++i) {
        const double t = d.t[i];
        if (t < 0.0 || std::fabs(t - t_lost) < 0.1 || std::fabs(t - t_back) < 0.1) continue;
        const double want = (t > t_lost && t < t_back) ? 1.0 : 0.0;
        wrong += d.v[i] != want;
        ++checked;
    }
    EXPECT_EQ(wrong, 0) << "gnss_denied differs from the expected phases in " << wrong << " of " << checked
                        << " rows (" << dir << ")";
}

}  // namespace

// An outage that ends: GNSS samples dropped in [100.5, 300) s (the 100 s fix is the last before it, as in the paper
// scenario; the 300 s fix is the first after it), for three seeds.
//
// The bound on the error after re-acquisition: the re-acquisition resets the aided filter on the fixes, so its
// horizontal error is again the fix error as seen through the aided EKF. The fix error is white (2.12 m per axis per
// fix, averaged by the filter) plus an ionospheric random walk (0.16 m per axis per 60 s node; config/sensors/gnss/
// baseline.yaml) that moves the slow part between the pre-outage window ([0, 100) s) and the post window
// ([305, 500] s, centres 325 s apart, ~5.4 nodes) by 0.37 m per axis (1 sigma): |change| < 1.4 m with 99.9 %
// probability. So the post-window mean must be within 2 m of the pre-outage mean and its max within 3 m of the
// pre-outage max (the max adds the white part's excursions). As a second reference, the same seed with GNSS
// never interrupted: the post-window mean within 0.5 m of that run's (both filters track the same fixes; measured
// differences <= 0.13 m). The outage itself reaches 19-71 m in these seeds (printed), so a filter that failed to
// re-acquire, or re-acquired by blending slowly, fails the test.
TEST(GnssFaults, OutageThatEndsIsReacquiredToTheAidedLevel) {
    const char* const kOutage = "faults=[{at_s: 100.5, until_s: 300, target: sensors_gnss, kind: drop}]";
    const double kLastFix = 100.0, kFirstFix = 300.0, kTimeout = 1.5, kFixPeriod = 1.0;
    const int kReacquireFixes = 5;  // config/nav/tuning.yaml position.gnss_integrity.reacquire_fixes
    std::printf("outage [100.5, 300) s, scenario #2, direct layout; horizontal error [m]\n");
    std::printf("seed | lost at | re-acquired at | pre [0,100) mean/max | outage max | post [305,500] mean/max | "
                "GNSS kept: post mean/max\n");
    for (const int seed : {1, 2, 3}) {
        SCOPED_TRACE("seed " + std::to_string(seed));
        const RunOut f = run_s2("gnss-outage", seed, {kGnssKept, kOutage});
        ASSERT_EQ(f.result.exit_code, 0) << f.result.output;
        const RunOut ref = run_s2("gnss-kept", seed, {kGnssKept});
        ASSERT_EQ(ref.result.exit_code, 0) << ref.result.output;
        const std::string& log = f.result.output;

        const auto lost = events(log, "nav_pos", "GNSS lost: no valid fix");
        const auto back = events(log, "nav_pos", "GNSS re-acquired");
        ASSERT_EQ(lost.size(), 1u) << log;
        ASSERT_EQ(back.size(), 1u) << log;
        // Lost at the first step more than 1.5 s after the last fix; back at the 5th returned fix.
        EXPECT_GT(lost[0], kLastFix + kTimeout);
        EXPECT_LE(lost[0], kLastFix + kTimeout + 2 * kDt);
        EXPECT_GT(back[0], kFirstFix);
        EXPECT_LE(back[0], kFirstFix + (kReacquireFixes - 1) * kFixPeriod + 1e-6);
        EXPECT_TRUE(events(ref.result.output, "nav_pos", "GNSS (lost|re-acquired)").empty()) << ref.result.output;
        const std::string eor = end_of_run(log, "nav_pos");
        EXPECT_EQ(count(eor, "re-acquisitions"), 1) << eor;
        EXPECT_EQ(count(eor, "chi-square gate"), 0) << eor;
        EXPECT_EQ(count(eor, "refused for re-acquisition"), 0) << eor;
        expect_denied_between(f.dir, lost[0], back[0]);

        const Series hor = series(f.dir, "error", "hor_m"), hor_ref = series(ref.dir, "error", "hor_m");
        ASSERT_FALSE(hor.t.empty());
        ASSERT_FALSE(hor_ref.t.empty());
        const WindowStats pre = stats(hor, 0.0, 100.0), outage = stats(hor, lost[0], back[0]),
                          post = stats(hor, back[0] + 1.0, 501.0), post_ref = stats(hor_ref, back[0] + 1.0, 501.0);
        std::printf("%4d | %7.2f | %14.2f | %9.2f / %5.2f | %10.1f | %12.2f / %5.2f | %9.2f / %5.2f\n", seed, lost[0],
                    back[0], pre.mean, pre.max, outage.max, post.mean, post.max, post_ref.mean, post_ref.max);
        ASSERT_TRUE(pre.finite && outage.finite && post.finite && post_ref.finite);
        ASSERT_GT(post.n, 1900);  // ~195 s of 10 Hz rows
        EXPECT_LE(post.mean, pre.mean + 2.0);
        EXPECT_LE(post.max, pre.max + 3.0);
        EXPECT_NEAR(post.mean, post_ref.mean, 0.5);
    }
}

// Spoofing: from 200 s to 220 s every fix is moved 500 m north (a latitude bias), GNSS otherwise available.
// Expected, from the design (docs/navigation.md, "GNSS integrity and re-acquisition"): the 200-204 s fixes rejected
// by the chi-square gate (d2 ~ 5e4 against the gate's 40), the source untrusted at the 5th (204 s) and the filter
// GNSS-denied; the 15 spoofed fixes 205-219 s refused for re-acquisition (500 m is outside the 100 m + 3 m/s
// dead-reckoning bound for the first 133 s); the genuine fixes from 220 s re-acquire at 224 s.
// Bound during the spoof: the aided error of the same run before it plus 5 m, i.e. 24 s of GNSS-denied dead
// reckoning at 0.2 m/s, twice the drift rate measured in scenario #2 (~0.1 m/s); a filter that followed the spoofed
// fixes even for one update would be off by hundreds of metres.
TEST(GnssFaults, SpoofedJumpIsRejectedAndGnssReacquiredAfterIt) {
    const double kFrom = 200.0, kUntil = 220.0;
    const double bias = lat_offset_rad(500.0);
    char fault[200];
    std::snprintf(fault, sizeof(fault),
                  "faults=[{at_s: %.0f, until_s: %.0f, target: sensors_gnss, kind: bias, fields: {lat_rad: %.6e}}]",
                  kFrom, kUntil, bias);
    const RunOut f = run_s2("gnss-spoof", 1, {kGnssKept, fault});
    ASSERT_EQ(f.result.exit_code, 0) << f.result.output;
    const std::string& log = f.result.output;

    const std::regex gate_re("\\[nav_pos\\] step [0-9]+ t=([-0-9.]+) s: GNSS fix rejected by the chi-square gate: "
                             "d2 = ([0-9.e+]+) > ([0-9.]+)");
    std::smatch m;
    ASSERT_TRUE(std::regex_search(log, m, gate_re)) << log;
    const double t_gate = std::stod(m[1].str()), d2 = std::stod(m[2].str()), gate = std::stod(m[3].str());
    const auto untrusted = events(log, "nav_pos", "GNSS lost: fix source untrusted");
    const auto back = events(log, "nav_pos", "GNSS re-acquired");
    const std::string eor = end_of_run(log, "nav_pos");
    const long n_gate = count(eor, "chi-square gate"), n_refused = count(eor, "refused for re-acquisition");

    const Series hor = series(f.dir, "error", "hor_m");
    ASSERT_FALSE(hor.t.empty());
    const double t_back = back.empty() ? 500.0 : back[0];
    const WindowStats pre = stats(hor, 0.0, kFrom), during = stats(hor, kFrom, t_back + 1.0),
                      after = stats(hor, t_back + 1.0, 501.0);
    std::printf("spoofing +500 m north (lat_rad %+.4e) in [%.0f, %.0f) s, seed 1:\n", bias, kFrom, kUntil);
    std::printf("  first gate rejection at %.2f s, d2 = %.1f > %.0f; untrusted at %.2f s; re-acquired at %.2f s\n",
                t_gate, d2, gate, untrusted.empty() ? std::nan("") : untrusted[0], t_back);
    std::printf("  end of run: %ld fixes rejected by the gate, %ld refused for re-acquisition\n", n_gate, n_refused);
    std::printf("  horizontal error: before mean %.2f max %.2f m; spoof to re-acquisition + 1 s max %.2f m "
                "(bound %.2f); after mean %.2f max %.2f m\n",
                pre.mean, pre.max, during.max, pre.max + 5.0, after.mean, after.max);

    EXPECT_NEAR(t_gate, kFrom, 1e-6);
    EXPECT_GT(d2, 100.0 * gate);
    ASSERT_EQ(untrusted.size(), 1u) << log;
    EXPECT_NEAR(untrusted[0], kFrom + 4.0, 1e-6);  // the 5th consecutive rejected fix
    ASSERT_EQ(back.size(), 1u) << log;
    EXPECT_NEAR(back[0], kUntil + 4.0, 1e-6);  // the 5th genuine fix
    EXPECT_EQ(n_gate, 5) << eor;
    EXPECT_EQ(n_refused, std::lround(kUntil - kFrom) - 5) << eor;
    EXPECT_EQ(count(eor, "re-acquisitions"), 1) << eor;
    EXPECT_EQ(events(log, "nav_pos", "GNSS lost").size(), 1u) << log;
    expect_denied_between(f.dir, untrusted[0], back[0]);
    ASSERT_TRUE(pre.finite && during.finite && after.finite);
    EXPECT_LE(during.max, pre.max + 5.0);
    EXPECT_LE(after.mean, pre.mean + 2.0);  // the aided level again (see the outage test for the 2 m)
}

// NaN samples, one topic at a time, in one run of the unchanged paper scenario (GNSS lost for good at 100 s):
//   ImuSample f_b [40, 40.5) s and w_b [300, 300.2) s (70 samples; both nav_att and nav_pos check the whole sample),
//   GnssSample lat [60, 61) s (one fix epoch, 60 s: with one fix missing the 1.5 s timeout declares GNSS lost at
//   60.51 s and the fixes 61-65 s re-acquire it), MagSample [150, 151) s, AirSample [200, 201) s, AtmSample
//   [250, 251) s (100 samples each).
// Closeness to the fault-free run of the same seed: the faults remove 0.7 s of IMU, 1 s of each other sensor and
// one fix (a 4.5 s denied episode before t_GNSS), which perturbs the state at 100 s slightly; over seeds 1-5 the
// final horizontal errors differed by <= 5.2 m (3 % of the error), the mean attitude errors by <= 5 %, the final
// altitude errors by <= 0.8 m. Bounds: 10 % + 5 m, 20 %, 2 m.
TEST(GnssFaults, NanSamplesAreRejectedCountedAndHarmless) {
    struct NanFault {
        const char* target;
        const char* field;
        double at_s, until_s;
    };
    const NanFault faults[] = {{"sensors_inertial", "f_b_mps2", 40.0, 40.5}, {"sensors_gnss", "lat_rad", 60.0, 61.0},
                               {"sensors_magnetic", "b_b_nT", 150.0, 151.0}, {"sensors_air", "tas_mps", 200.0, 201.0},
                               {"sensors_atmospheric", "p_Pa", 250.0, 251.0},
                               {"sensors_inertial", "w_b_rps", 300.0, 300.2}};
    std::string list = "faults=[";
    long imu = 0, mag = 0, air = 0, atm = 0, fixes = 0;
    for (const NanFault& nf : faults) {
        char e[160];
        std::snprintf(e, sizeof(e), "%s{at_s: %g, until_s: %g, target: %s, kind: nan, fields: [%s]}",
                      list.size() > 8 ? ", " : "", nf.at_s, nf.until_s, nf.target, nf.field);
        list += e;
        const std::string t = nf.target;
        const long n = steps(nf.at_s, nf.until_s);
        if (t == "sensors_inertial") imu += n;
        if (t == "sensors_magnetic") mag += n;
        if (t == "sensors_air") air += n;
        if (t == "sensors_atmospheric") atm += n;
        if (t == "sensors_gnss")  // fix epochs (1 Hz, on whole seconds) in the window; other samples carry no fix
            fixes += static_cast<long>(std::ceil(nf.until_s - 1e-9) - std::ceil(nf.at_s - 1e-9));
    }
    list += "]";
    const RunOut f = run_s2("gnss-nan", 1, {list});
    ASSERT_EQ(f.result.exit_code, 0) << f.result.output;
    const RunOut ref = run_s2("gnss-nan-ref", 1, {});
    ASSERT_EQ(ref.result.exit_code, 0) << ref.result.output;
    const std::string& log = f.result.output;

    const std::string att = end_of_run(log, "nav_att"), pos = end_of_run(log, "nav_pos"),
                      adf = end_of_run(log, "nav_air");
    std::printf("NaN faults, seed 1: expected ImuSample %ld, MagSample %ld, AirSample %ld, AtmSample %ld, fixes %ld\n",
                imu, mag, air, atm, fixes);
    std::printf("  %s\n  %s\n  %s\n", att.c_str(), pos.c_str(), adf.c_str());
    EXPECT_EQ(count(att, "ImuSample"), imu) << att;
    EXPECT_EQ(count(att, "MagSample"), mag) << att;
    EXPECT_EQ(count(att, "(p_n)"), 0) << att;
    EXPECT_EQ(count(pos, "ImuSample"), imu) << pos;
    EXPECT_EQ(count(pos, "GnssSample (invalid)"), fixes) << pos;
    EXPECT_EQ(count(pos, "AirDataEstimate"), 0) << pos;
    EXPECT_EQ(count(pos, "AttitudeEstimate"), 0) << pos;
    EXPECT_EQ(count(adf, "AirSample"), air) << adf;
    EXPECT_EQ(count(adf, "AtmSample"), atm) << adf;
    // The counts also went out on ComponentStatus (MODE) on the last step.
    for (const char* member : {"nav_att", "nav_pos", "nav_air"})
        EXPECT_EQ(events(log, member, "end of run: rejected samples").size(), 1u) << member << "\n" << log;
    // The missing fix: lost 1.5 s after the 59 s fix, back at the 5th of the fixes from 61 s; then the paper's loss.
    const auto lost = events(log, "nav_pos", "GNSS lost"), back = events(log, "nav_pos", "GNSS re-acquired");
    ASSERT_EQ(lost.size(), 2u) << log;
    ASSERT_EQ(back.size(), 1u) << log;
    EXPECT_NEAR(lost[0], 60.51, 1e-6);
    EXPECT_NEAR(back[0], 65.0, 1e-6);
    EXPECT_NEAR(lost[1], 101.51, 1e-6);

    // Finite estimates and errors throughout (t >= 0), and close to the fault-free run.
    for (const char* col : {"lat_rad", "lon_rad", "h_m", "vn_mps", "yaw_rad", "pitch_rad", "bank_rad", "tas_mps",
                            "aoa_rad", "dT_K"}) {
        const Series s = series(f.dir, "estimate", col);
        ASSERT_FALSE(s.t.empty()) << col;
        EXPECT_TRUE(stats(s, 0.0, 501.0).finite) << "estimate " << col << " not finite";
    }
    const auto rec = gdnav::metrics::read_run_record(f.dir / "metrics.yaml");
    const auto base = gdnav::metrics::read_run_record(ref.dir / "metrics.yaml");
    ASSERT_TRUE(rec.complete && base.complete);
    for (const auto& s : rec.signals)
        EXPECT_TRUE(std::isfinite(s.mean) && std::isfinite(s.std) && std::isfinite(s.max) && std::isfinite(s.final));
    const double hor = rec[Signal::hor].final, hor0 = base[Signal::hor].final;
    const double rot = rec[Signal::rot].mean / kDeg, rot0 = base[Signal::rot].mean / kDeg;
    const double h = rec[Signal::h].final, h0 = base[Signal::h].final;
    std::printf("  faulted vs fault-free: final horizontal %.2f vs %.2f m; mean attitude %.4f vs %.4f deg; final "
                "altitude %.2f vs %.2f m; max |TAS error| %.3f vs %.3f m/s\n",
                hor, hor0, rot, rot0, h, h0, std::fabs(rec[Signal::tas].max), std::fabs(base[Signal::tas].max));
    EXPECT_LE(std::fabs(hor - hor0), 0.1 * hor0 + 5.0);
    EXPECT_LE(std::fabs(rot - rot0), 0.2 * rot0);
    EXPECT_LE(std::fabs(h - h0), 2.0);
}
