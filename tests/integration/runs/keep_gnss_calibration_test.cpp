// The variant keep_gnss_calibration (docs/navigation.md, "Keeping the GNSS calibration") in real gdnav runs of the
// paper's scenario #2, cut 10 s after the GNSS loss: the direct, composed and distributed layouts record the same bits
// (attitude and position estimates, metrics.yaml); nav_att's joint GNSS/INS estimator ends its GNSS-aided phase and
// goes on with air data and the magnetometer at the step nav_pos goes GNSS-denied, logged once; the variant really
// changes the run.
#include <gtest/gtest.h>

#include <cmath>
#include <regex>
#include <string>
#include <vector>

#include "process_util.hpp"
#include "record_reader.hpp"
#include "temp_dir.hpp"

using namespace gdnav::testing;
namespace fs = std::filesystem;

namespace {

struct Flown {
    Result r;
    fs::path out;
    std::string metrics;
    std::map<std::string, std::string> digests;
};

Flown fly(const std::string& layout, const std::string& variant, const std::string& tag) {
    Flown f;
    f.out = temp_dir(tag);
    std::vector<std::string> args = {kExe,     "run",    "--scenario", "paper2", "--seed",   "4",
                                     "--run",  "1",      "--steps",    "16000",  "--layout", layout,
                                     "--record", "AttitudeEstimate,PositionEstimate", "--out", f.out.string()};
    if (!variant.empty()) args.insert(args.end(), {"--variant", variant});
    f.r = run(args, 300.0);
    EXPECT_EQ(f.r.exit_code, 0) << f.r.output;
    f.metrics = read_file(f.out / "metrics.yaml");
    EXPECT_NE(f.metrics.find("\ncomplete: true\n"), std::string::npos) << tag;
    f.digests = read_digests(f.out);
    return f;
}

// The first recorded step at which nav_pos is GNSS-denied; NaN if none.
double first_denied_t(const fs::path& out) {
    for (const auto& p : read_records<gdnav::msg::PositionEstimate>(out, "gdnav/PositionEstimate"))
        if (p.gnss_denied()) return p.stamp().t_s();
    return std::nan("");
}

// The time nav_att's estimator went on without GNSS, from its status line; NaN if none.
double handed_over_at(const std::string& log) {
    std::smatch m;
    const std::regex line("\\[nav_att\\][^\\n]*GNSS lost at t = (-?[0-9.]+) s: the GNSS/INS estimator goes on");
    if (!std::regex_search(log, m, line))
        return std::nan("");
    return std::stod(m[1]);
}

}  // namespace

TEST(KeepGnssCalibration, SameBitsInEveryLayoutAndTheHandOverAtTheLossStep) {
    const std::string kgc = "keep_gnss_calibration";
    const Flown direct = fly("direct", kgc, "kgc-direct");
    const Flown composed = fly("composed", kgc, "kgc-composed");
    const Flown distributed = fly("distributed", kgc, "kgc-distributed");
    ASSERT_EQ(direct.digests.size(), 2u) << direct.r.output;
    for (const Flown* f : {&composed, &distributed}) {
        EXPECT_EQ(f->digests, direct.digests);
        EXPECT_EQ(f->metrics, direct.metrics);
    }
    for (const Flown* f : {&direct, &composed, &distributed}) {
        EXPECT_EQ(count_of(f->r.output, "the GNSS/INS estimator goes on with air data and the magnetometer"), 1u)
            << f->r.output;
        // The step nav_pos went denied is the step nav_att's estimator went on without GNSS.
        const double t_denied = first_denied_t(f->out);
        const double t_hand = handed_over_at(f->r.output);
        std::printf("nav_att's estimator without GNSS from t = %.2f s, nav_pos denied from t = %.2f s\n", t_hand,
                    t_denied);
        ASSERT_FALSE(std::isnan(t_hand)) << f->r.output;
        EXPECT_NEAR(t_hand, t_denied, 1e-6);
        EXPECT_GT(t_hand, 100.0);  // the paper's loss at t = 100 s plus the 1.5-s timeout
    }
    // The variant is really selected: the paper's filters give other bits.
    const Flown paper = fly("direct", "", "kgc-paper");
    EXPECT_NE(paper.digests, direct.digests);
    EXPECT_EQ(paper.r.output.find("GNSS/INS estimator"), std::string::npos);
    for (const Flown* f : {&direct, &composed, &distributed, &paper}) fs::remove_all(f->out);
}

// The hand-over form: the paper's attitude filter takes over from the estimator at the step nav_pos goes denied.
TEST(KeepGnssCalibration, TheHandOverFormHandsOverAtTheLossStep) {
    const Flown f = fly("direct", "gnss_calibration_handover", "kgc-handover");
    EXPECT_EQ(count_of(f.r.output, "the attitude filter takes over from the GNSS/INS estimator"), 1u) << f.r.output;
    std::smatch m;
    const std::regex line("\\[nav_att\\][^\\n]*GNSS lost at t = (-?[0-9.]+) s: the attitude filter takes over");
    ASSERT_TRUE(std::regex_search(f.r.output, m, line)) << f.r.output;
    EXPECT_NEAR(std::stod(m[1]), first_denied_t(f.out), 1e-6);
    fs::remove_all(f.out);
}

TEST(KeepGnssCalibration, TheOldPerComponentAlignerSectionInNavPosIsOneClearError) {
    const Result r = run({kExe, "run", "--scenario", "paper2_calibrated", "--steps", "10", "--layout", "direct", "--set",
                          "components.nav_pos.in_flight_alignment={}", "--out", temp_dir("kgc-bad").string()},
                         60.0);
    EXPECT_NE(r.exit_code, 0);
    EXPECT_NE(r.output.find("follow_in_flight_alignment"), std::string::npos) << r.output;
}

// A 10-step run of scenario #2 with a variant file of this content: its output and exit code.
static Result run_with_variant(const std::string& tag, const std::string& content) {
    const fs::path dir = temp_dir(tag);
    const fs::path variant = dir / "variant.yaml";
    gdnav::test::write_text(variant, content);
    Result r = run({kExe, "run", "--scenario", "paper2", "--steps", "10", "--layout", "direct", "--variant",
                    variant.string(), "--out", (dir / "out").string()},
                   60.0);
    fs::remove_all(dir);
    return r;
}

TEST(KeepGnssCalibration, TheDeniedPhaseEstimatorWithoutTheAidedOneIsOneClearError) {
    const Result r = run_with_variant("kgc-bad-variant", "denied_attitude: gnss_ins\nattitude: {specific_force: baseline}\n"
                                                         "position: {horizontal: frozen_wind, vertical: pressure}\n");
    EXPECT_NE(r.exit_code, 0);
    EXPECT_NE(r.output.find("denied_attitude"), std::string::npos) << r.output;
    EXPECT_NE(r.output.find("needs aided_attitude: gnss_ins"), std::string::npos) << r.output;
}

TEST(KeepGnssCalibration, TheEstimatorsWindWithoutTheDeniedPhaseEstimatorIsOneClearError) {
    const Result r = run_with_variant("kgc-bad-wind", "attitude: {specific_force: baseline}\n"
                                                      "position: {horizontal: frozen_wind, vertical: pressure, "
                                                      "wind_at_loss: gnss_ins}\n");
    EXPECT_NE(r.exit_code, 0);
    EXPECT_NE(r.output.find("position.wind_at_loss"), std::string::npos) << r.output;
    EXPECT_NE(r.output.find("needs denied_attitude: gnss_ins"), std::string::npos) << r.output;
}
