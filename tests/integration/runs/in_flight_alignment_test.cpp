// In-flight fine alignment (docs/navigation.md, "In-flight fine alignment") in real gdnav runs of the calibrated
// scenario #2, cut after the hand-over: nav_att runs the aligner and nav_pos follows it (gdnav/NavHandover); both hand
// over at the same step, in one process and in separate processes alike, with the same attitude estimates bit for bit; the
// published attitude does not jump at the hand-over (the attitude filter starts from the aligner's attitude); each
// hand-over is logged once.
#include <gtest/gtest.h>

#include <cmath>
#include <regex>

#include "process_util.hpp"
#include "record_reader.hpp"

using namespace gdnav::testing;
namespace fs = std::filesystem;

namespace {

constexpr const char* kSteps = "16000";  // the scenario hands over at the paper's t0 = -50 s, step 15 700

std::vector<gdnav::msg::AttitudeEstimate> fly(const fs::path& out, const std::string& layout, Result& r) {
    r = run({kExe, "run", "--scenario", "paper2_calibrated", "--seed", "1", "--run", "0", "--layout", layout, "--steps",
             kSteps, "--record", "AttitudeEstimate", "--out", out.string()},
            280.0);
    EXPECT_EQ(r.exit_code, 0) << r.output;
    return read_records<gdnav::msg::AttitudeEstimate>(out, "gdnav/AttitudeEstimate");
}

// The hand-over time in `who`'s status line, NaN if none.
double handed_over_at(const std::string& log, const std::string& who, const std::string& text) {
    std::smatch m;
    if (!std::regex_search(log, m, std::regex("\\[" + who + "\\][^\\n]*" + text + " at t = (-?[0-9.]+) s")))
        return std::nan("");
    return std::stod(m[1]);
}

}  // namespace

TEST(InFlightAlignment, NavAttAndNavPosHandOverAtTheSameStepInOneProcessAndInSeveral) {
    const fs::path a = temp_dir("ifa-direct"), b = temp_dir("ifa-distributed");
    Result ra, rb;
    const auto direct = fly(a, "direct", ra);
    const auto distributed = fly(b, "distributed", rb);
    for (const Result* r : {&ra, &rb}) {
        const double t_att = handed_over_at(r->output, "nav_att", "in-flight alignment");
        const double t_pos = handed_over_at(r->output, "nav_pos", "aligned");
        ASSERT_FALSE(std::isnan(t_att)) << r->output;
        EXPECT_EQ(t_att, t_pos) << r->output;
        EXPECT_EQ(count_of(r->output, "in-flight alignment at t ="), 1u) << r->output;
        EXPECT_EQ(count_of(r->output, "aligned at t ="), 1u) << r->output;
        EXPECT_EQ(t_att, handed_over_at(ra.output, "nav_att", "in-flight alignment"));
    }
    ASSERT_EQ(direct.size(), distributed.size());
    ASSERT_GT(direct.size(), 10000u);
    const auto angle_deg = [](const auto& p, const auto& q) {
        const double dot = std::fabs(p[0] * q[0] + p[1] * q[1] + p[2] * q[2] + p[3] * q[3]);
        return 2.0 * std::acos(std::min(1.0, dot)) * 180.0 / std::acos(-1.0);
    };
    const double t_hand = handed_over_at(ra.output, "nav_att", "in-flight alignment");
    // The attitude turns by up to omega dt per step (0.07 deg in a 20-degree-bank turn); the hand-over step (a fix
    // step) adds the aligner's fix update, within its sigmas (heading <= 0.05 deg), not a restart's jump.
    double jump_deg = -1.0, before_deg = 0.0;
    for (std::size_t i = 0; i < direct.size(); ++i) {
        ASSERT_EQ(direct[i].stamp().step(), distributed[i].stamp().step());
        ASSERT_EQ(direct[i].q_nb(), distributed[i].q_nb()) << "step " << direct[i].stamp().step();
        if (i < 11) continue;
        if (std::fabs(direct[i].stamp().t_s() - t_hand) < 1e-6) {
            jump_deg = angle_deg(direct[i - 1].q_nb(), direct[i].q_nb());
            for (std::size_t j = i - 10; j < i; ++j)
                before_deg = std::max(before_deg, angle_deg(direct[j - 1].q_nb(), direct[j].q_nb()));
        }
    }
    std::printf("hand-over at t = %.2f s; attitude change over the hand-over step %.4f deg, over the 10 steps before "
                "at most %.4f deg\n",
                t_hand, jump_deg, before_deg);
    ASSERT_GE(jump_deg, 0.0) << "no sample at the hand-over";
    EXPECT_LT(jump_deg, before_deg + 0.03);
    fs::remove_all(a);
    fs::remove_all(b);
}

TEST(InFlightAlignment, ItNeedsTheTruthFreeStartAndExcludesTheGnssYawOption) {
    Result r = run({kExe, "run", "--scenario", "paper2_calibrated", "--steps", "10", "--layout", "direct", "--set",
                    "components.nav_att.init_mode=alignment", "--out", temp_dir("ifa-bad1").string()},
                   60.0);
    EXPECT_NE(r.exit_code, 0);
    EXPECT_NE(r.output.find("in_flight_alignment"), std::string::npos) << r.output;
    EXPECT_NE(r.output.find("init_mode: measurements"), std::string::npos) << r.output;
    r = run({kExe, "run", "--scenario", "paper2_calibrated", "--steps", "10", "--layout", "direct", "--set",
             "components.nav_att.yaw_from_gnss={}", "--out", temp_dir("ifa-bad2").string()},
            60.0);
    EXPECT_NE(r.exit_code, 0);
    EXPECT_NE(r.output.find("yaw_from_gnss"), std::string::npos) << r.output;
}
