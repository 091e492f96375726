// import-log then export-log: a flight log sampled on the step grid comes back with the same values (samples on a
// grid instant are taken as they are; export writes 17 significant digits), and GNSS fixes come back at their steps.
#include <cmath>

#include <gtest/gtest.h>

#include "config/config.hpp"
#include "temp_dir.hpp"
#include "framework/topic_types.hpp"
#include "io/flight_log/csv_table.hpp"
#include "io/flight_log/log_export.hpp"
#include "io/flight_log/log_import.hpp"
#include "io/flight_log/log_layout.hpp"

namespace gdnav::io::flight_log {
namespace {

namespace fs = std::filesystem;

constexpr double kDt = 0.01;
constexpr std::size_t kRows = 21;  // t = 0 .. 0.2 s

std::vector<std::string> columns_of(const LogGroup& g) {
    std::vector<std::string> c{kTimeColumn};
    for (const auto& f : g.fields) c.push_back(f.name);
    return c;
}

// A distinct finite value for each group, column and row.
double value(std::size_t group, std::size_t column, std::size_t row) {
    return 1000.0 * static_cast<double>(group + 1) + static_cast<double>(column) + 0.001 * static_cast<double>(row);
}

// Continuous groups: one row per grid step; gnss: fixes at steps 5 and 15.
void write_log(const fs::path& dir) {
    fs::create_directories(dir);
    for (std::size_t gi = 0; gi < log_groups().size(); ++gi) {
        const LogGroup& g = log_groups()[gi];
        CsvWriter w(dir / (g.name + ".csv"), columns_of(g));
        for (std::size_t k = 0; k < kRows; ++k) {
            if (g.fixes && k != 5 && k != 15) continue;
            std::vector<double> row{static_cast<double>(k) * kDt};
            for (std::size_t c = 0; c < g.fields.size(); ++c) row.push_back(value(gi, c, k));
            w.row(row);
        }
        w.close();
    }
}

class LogRoundTrip : public ::testing::Test {
protected:
    void SetUp() override { framework::register_gdnav_topics(); }
    test::TempDir t_;
};

TEST_F(LogRoundTrip, ImportedLogExportsTheSameValues) {
    write_log(t_.path() / "in");
    ImportOptions io;
    io.csv_dir = t_.path() / "in";
    io.run_dir = t_.path() / "run";
    io.t0_s = 0.0;
    io.dt_s = kDt;
    import_log(io);
    ExportOptions eo;
    eo.run_dir = io.run_dir;
    eo.csv_dir = t_.path() / "out";
    export_log(eo);

    for (std::size_t gi = 0; gi < log_groups().size(); ++gi) {
        const LogGroup& g = log_groups()[gi];
        const CsvTable table = read_csv(eo.csv_dir / (g.name + ".csv"), columns_of(g));
        const std::vector<std::size_t> steps =
            g.fixes ? std::vector<std::size_t>{5, 15} : [] {
                std::vector<std::size_t> all(kRows);
                for (std::size_t k = 0; k < kRows; ++k) all[k] = k;
                return all;
            }();
        ASSERT_EQ(table.rows(), steps.size()) << g.name;
        for (std::size_t r = 0; r < steps.size(); ++r) {
            EXPECT_NEAR(table.at(r, 0), static_cast<double>(steps[r]) * kDt, 1e-12) << g.name << " row " << r;
            for (std::size_t c = 0; c < g.fields.size(); ++c)
                EXPECT_EQ(table.at(r, c + 1), value(gi, c, steps[r])) << g.name << " " << g.fields[c].name;
        }
    }
}

TEST_F(LogRoundTrip, ExportAtAGroupRateKeepsEveryNthStep) {
    write_log(t_.path() / "in");
    ImportOptions io;
    io.csv_dir = t_.path() / "in";
    io.run_dir = t_.path() / "run";
    import_log(io);
    ExportOptions eo;
    eo.run_dir = io.run_dir;
    eo.csv_dir = t_.path() / "out";
    eo.rates_hz["mag"] = 20.0;  // every 5th step of the 100 Hz grid
    export_log(eo);
    const CsvTable mag = read_csv(eo.csv_dir / "mag.csv", columns_of(log_groups()[1]));
    ASSERT_EQ(mag.rows(), 5u);  // steps 0, 5, 10, 15, 20
    for (std::size_t r = 0; r < mag.rows(); ++r) EXPECT_EQ(mag.at(r, 1), value(1, 0, 5 * r));
}

TEST_F(LogRoundTrip, BadInputsAreOneLineErrors) {
    ImportOptions io;
    io.csv_dir = t_.path() / "missing";
    io.run_dir = t_.path() / "run";
    try {
        import_log(io);
        FAIL() << "no error";
    } catch (const config::ConfigError& e) {
        EXPECT_EQ(std::string(e.what()), "config error: " + io.csv_dir.string() + ": not a directory");
    }
    ExportOptions eo;
    eo.run_dir = t_.path();
    eo.csv_dir = t_.path() / "out";
    eo.rates_hz["gyro"] = 10.0;
    try {
        export_log(eo);
        FAIL() << "no error";
    } catch (const config::ConfigError& e) {
        EXPECT_EQ(std::string(e.what()),
                  "config error: --rates: unknown sensor group 'gyro' (known: imu, mag, air, atm, gnss)");
    }
}

}  // namespace
}  // namespace gdnav::io::flight_log
