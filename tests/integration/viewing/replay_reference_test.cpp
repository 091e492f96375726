// An imported flight log scores the filters only against a reference trajectory (docs/replay.md, "Reference
// trajectory"), with real gdnav processes:
//   (a) without --reference, a replay writes no error metrics: metrics.yaml says `reference: none`, the run log says
//       so once, run.h5 has no errors;
//   (b) with the run's own recorded truth as the reference (export-log's reference.csv, SI and quaternion), the
//       replay's metrics.yaml equals the original run's byte for byte; in degrees and Euler angles it matches to
//       rounding;
//   (c) a reference that does not cover the grid, or whose quaternion is not a unit one, is one error line, exit 2.
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <sstream>

#include <yaml-cpp/yaml.h>

#include "h5_column.hpp"
#include "process_util.hpp"
#include "record_reader.hpp"

using namespace gdnav::testing;
namespace fs = std::filesystem;

namespace {

// 16 001 steps from t0 = -50 s: 10 s past the GNSS loss at t = 100 s.
const std::string kSteps = "16001";
const std::string kSensors = "ImuSample,MagSample,AirSample,AtmSample,GnssSample";
constexpr int kDomain = 232;  // this test's own DDS domain (integration tests run one at a time)

Result replay(const fs::path& imported, const std::string& topics, const fs::path& out) {
    return run({GDNAV_GDNAV_EXE, "run", "--scenario", "paper2", "--seed", "1", "--steps", kSteps, "--replay",
                imported.string(), "--topics", topics, "--layout", "composed", "--domain", std::to_string(kDomain),
                "--out", out.string()},
               240.0);
}

// reference.csv rewritten with latitude, longitude and the Euler angles (from the recorded Truth) in degrees.
void write_degree_reference(const fs::path& orig, const fs::path& to) {
    const auto truth = read_records<gdnav::msg::Truth>(orig, "gdnav/Truth");
    std::ofstream f(to);
    f << "# the same flight, degrees at the edge\n"
         "t_s,lat_deg,lon_deg,h_m,v_n_mps_0,v_n_mps_1,v_n_mps_2,yaw_deg,pitch_deg,bank_deg,tas_mps,aoa_rad,aos_rad,dT_K\n";
    f.precision(17);
    const double deg = 180.0 / M_PI;
    for (const auto& t : truth) {
        const auto& v = t.v_n_mps();
        const auto& e = t.euler_rad();
        f << t.stamp().t_s() << "," << t.lat_rad() * deg << "," << t.lon_rad() * deg << "," << t.h_m() << "," << v[0]
          << "," << v[1] << "," << v[2] << "," << e[0] * deg << "," << e[1] * deg << "," << e[2] * deg << ","
          << t.tas_mps() << "," << t.aoa_rad() << "," << t.aos_rad() << "," << t.dT_K() << "\n";
    }
}

// Exit code 2 and one error line containing every needle.
void expect_one_error(const Result& r, const std::vector<std::string>& needles) {
    EXPECT_EQ(r.exit_code, 2) << r.output;
    std::istringstream in(r.output);
    std::size_t lines = 0;
    for (std::string line; std::getline(in, line);) lines += line.find("error") != std::string::npos;
    EXPECT_EQ(lines, 1u) << r.output;
    for (const auto& n : needles) EXPECT_NE(r.output.find(n), std::string::npos) << "'" << n << "' not in: " << r.output;
}

}  // namespace

TEST(ReplayReference, ImportedLogScoresOnlyAgainstAReferenceAndItsOwnTruthGivesTheOriginalsMetrics) {
    const fs::path orig = temp_dir("ref-orig"), csv = temp_dir("ref-csv"), plain = temp_dir("ref-plain"),
                   withref = temp_dir("ref-with"), degrees = temp_dir("ref-deg"), rep = temp_dir("ref-rep");
    Result r = run({GDNAV_GDNAV_EXE, "run", "--scenario", "paper2", "--seed", "1", "--steps", kSteps, "--layout",
                    "direct", "--record", kSensors + ",Truth", "--out", orig.string()},
                   240.0);
    ASSERT_EQ(r.exit_code, 0) << r.output;
    // Every step of every group (the flight log at the grid rate, exact) and reference.csv from the recorded Truth.
    r = run({GDNAV_GDNAV_EXE, "export-log", orig.string(), "--out", csv.string()});
    ASSERT_EQ(r.exit_code, 0) << r.output;
    ASSERT_TRUE(fs::exists(csv / "reference.csv")) << r.output;

    // (a) No reference: no error metrics, said once.
    r = run({GDNAV_GDNAV_EXE, "import-log", csv.string(), "--out", plain.string(), "--t0", "-50"});
    ASSERT_EQ(r.exit_code, 0) << r.output;
    EXPECT_NE(r.output.find("no --reference"), std::string::npos) << r.output;
    r = replay(plain, kSensors, rep / "plain");
    ASSERT_EQ(r.exit_code, 0) << r.output;
    EXPECT_EQ(count_of(r.output, "nav_recorder: reference: none ("), 1u) << r.output;
    const YAML::Node m = YAML::LoadFile((rep / "plain" / "metrics.yaml").string());
    EXPECT_TRUE(m["complete"].as<bool>());
    EXPECT_EQ(m["reference"].as<std::string>(), "none");
    EXPECT_FALSE(m["signals"]);
    EXPECT_FALSE(m["final_percent"]);
    const auto hor = h5_column(rep / "plain" / "run.h5", "error", "hor_m");
    ASSERT_EQ(hor.size(), 1601u);
    EXPECT_TRUE(std::all_of(hor.begin(), hor.end(), [](double x) { return std::isnan(x); }));
    EXPECT_FALSE(std::isnan(h5_column(rep / "plain" / "run.h5", "estimate", "lat_rad").back()));  // estimates kept

    // (b) The run's own truth as the reference: the original's metrics, bit for bit (the reference rows are on the
    // grid and written with 17 digits, so the replayed Truth carries the original's position, velocity, attitude
    // quaternion and air data exactly, and the imported sensors are the original's).
    r = run({GDNAV_GDNAV_EXE, "import-log", csv.string(), "--out", withref.string(), "--t0", "-50", "--reference",
             (csv / "reference.csv").string()});
    ASSERT_EQ(r.exit_code, 0) << r.output;
    EXPECT_NE(r.output.find("16001 rows (lat/lon in rad, attitude as q_nb) -> gdnav/Truth"), std::string::npos)
        << r.output;
    r = replay(withref, kSensors + ",Truth", rep / "withref");
    ASSERT_EQ(r.exit_code, 0) << r.output;
    EXPECT_EQ(count_of(r.output, "reference: none"), 0u) << r.output;
    EXPECT_EQ(read_file(rep / "withref" / "metrics.yaml"), read_file(orig / "metrics.yaml"));

    // In degrees with Euler angles: equal to rounding. deg -> rad and Euler -> quaternion change the last bits
    // (relative 1e-16: 1e-9 m of position, 1e-15 rad of attitude), far below the bounds, which a wrong unit or axis
    // order exceeds by orders of magnitude (a yaw in radians read as degrees: metres and degrees of error).
    write_degree_reference(orig, csv / "reference_deg.csv");
    r = run({GDNAV_GDNAV_EXE, "import-log", csv.string(), "--out", degrees.string(), "--t0", "-50", "--reference",
             (csv / "reference_deg.csv").string()});
    ASSERT_EQ(r.exit_code, 0) << r.output;
    r = replay(degrees, kSensors + ",Truth", rep / "degrees");
    ASSERT_EQ(r.exit_code, 0) << r.output;
    const YAML::Node a = YAML::LoadFile((orig / "metrics.yaml").string());
    const YAML::Node b = YAML::LoadFile((rep / "degrees" / "metrics.yaml").string());
    for (const char* s : {"hor_m", "cross_m", "along_m", "h_m", "vn_mps"})
        EXPECT_NEAR(b["signals"][s]["final"].as<double>(), a["signals"][s]["final"].as<double>(), 1e-6) << s;
    for (const char* s : {"rot_rad", "yaw_rad", "pitch_rad", "bank_rad"})
        EXPECT_NEAR(b["signals"][s]["mean"].as<double>(), a["signals"][s]["mean"].as<double>(), 1e-12) << s;
    EXPECT_EQ(b["distance_since_gnss_m"].as<double>(), a["distance_since_gnss_m"].as<double>());  // velocity as is
    std::printf("original = replay with its own truth as reference: final horizontal error %.4f m, mean attitude "
                "error %.5f deg; in degrees: %.4f m, %.5f deg\n",
                a["signals"]["hor_m"]["final"].as<double>(), a["signals"]["rot_rad"]["mean"].as<double>() * 180 / M_PI,
                b["signals"]["hor_m"]["final"].as<double>(), b["signals"]["rot_rad"]["mean"].as<double>() * 180 / M_PI);

    // (c) Bad references.
    {
        std::ifstream in(csv / "reference.csv");
        std::ofstream shortf(csv / "short.csv"), skew(csv / "skew.csv");
        std::string line;
        for (int i = 0; std::getline(in, line); ++i) {
            if (i <= 100) shortf << line << "\n";  // t = -50 .. -49 s only
            if (i == 2) {  // q_nb_0 (the 8th column) of t = -49.99 s set to 0.5: norm != 1
                std::size_t p = 0;
                for (int c = 0; c < 7; ++c) p = line.find(',', p) + 1;
                line = line.substr(0, p) + "0.5" + line.substr(line.find(',', p));
            }
            skew << line << "\n";
        }
    }
    const std::vector<std::string> imp{GDNAV_GDNAV_EXE, "import-log", csv.string(), "--out", (rep / "bad").string(),
                                       "--t0", "-50", "--reference"};
    auto with = [&](const std::string& f) {
        auto v = imp;
        v.push_back((csv / f).string());
        return run(v);
    };
    expect_one_error(with("short.csv"), {"short.csv", "must cover every step", "--steps"});
    expect_one_error(with("skew.csv"), {"skew.csv:3", "q_nb_0..3", "is not 1"});
    expect_one_error(with("missing.csv"), {"missing.csv", "cannot open"});
    if (!::testing::Test::HasFailure())
        for (const auto& d : {orig, csv, plain, withref, degrees, rep}) fs::remove_all(d);
}
