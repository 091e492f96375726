#include "io/flight_log/csv_table.hpp"

#include <fstream>
#include <limits>

#include <gtest/gtest.h>

#include "config/config.hpp"
#include "temp_dir.hpp"

namespace gdnav::io::flight_log {
namespace {

namespace fs = std::filesystem;

std::string error_of(const fs::path& file, const std::vector<std::string>& columns) {
    try {
        (void)read_csv(file, columns);
    } catch (const config::ConfigError& e) {
        return e.what();
    }
    return "";
}

TEST(CsvTable, WriterRoundTripsDoublesExactly) {
    test::TempDir t;
    const fs::path f = t.path() / "x.csv";
    const std::vector<double> a{0.1, 1.0 / 3.0, 1e-300, -2.5e10};
    const std::vector<double> b{std::nextafter(1.0, 2.0), -0.0, 123456789.123456789,
                                std::numeric_limits<double>::max()};
    {
        CsvWriter w(f, {"p", "q", "r", "s"});
        w.row(a);
        w.row(b);
        w.close();
    }
    const CsvTable table = read_csv(f, {"p", "q", "r", "s"});
    ASSERT_EQ(table.rows(), 2u);
    for (std::size_t c = 0; c < 4; ++c) {
        EXPECT_EQ(table.at(0, c), a[c]) << c;
        EXPECT_EQ(table.at(1, c), b[c]) << c;
    }
    EXPECT_EQ(table.lines, (std::vector<std::size_t>{2, 3}));
}

TEST(CsvTable, ColumnsInTheRequestedOrderCommentsAndBlankLinesSkipped) {
    test::TempDir t;
    const fs::path f = t.path() / "x.csv";
    std::ofstream(f) << "# a comment\n b , a \n\n1, 2\n# another\n 3 ,4.5\n";
    const CsvTable table = read_csv(f, {"a", "b"});
    EXPECT_EQ(table.columns, (std::vector<std::string>{"a", "b"}));
    ASSERT_EQ(table.rows(), 2u);
    EXPECT_EQ(table.at(0, 0), 2.0);
    EXPECT_EQ(table.at(0, 1), 1.0);
    EXPECT_EQ(table.at(1, 0), 4.5);
    EXPECT_EQ(table.at(1, 1), 3.0);
    EXPECT_EQ(table.lines, (std::vector<std::size_t>{4, 6}));
}

TEST(CsvTable, ErrorsAreOneLineNamingFileLineAndColumn) {
    test::TempDir t;
    const fs::path f = t.path() / "x.csv";
    const std::string at = "config error: " + f.string() + ":";
    std::ofstream(f) << "a,b\n1,x\n";
    EXPECT_EQ(error_of(f, {"a", "b"}), at + "2: column 'b': 'x' is not a number");
    std::ofstream(f, std::ios::trunc) << "a,b\n1,nan\n";
    EXPECT_EQ(error_of(f, {"a", "b"}), at + "2: column 'b': nan (NaN and infinite values are not allowed)");
    std::ofstream(f, std::ios::trunc) << "a\n1\n";
    EXPECT_EQ(error_of(f, {"a", "b"}), at + "1: missing column 'b'");
    std::ofstream(f, std::ios::trunc) << "a,b,c\n1,2,3\n";
    EXPECT_EQ(error_of(f, {"a", "b"}), at + "1: unknown column 'c' (expected: a, b)");
    std::ofstream(f, std::ios::trunc) << "a,b\n1,2,3\n";
    EXPECT_EQ(error_of(f, {"a", "b"}), at + "2: 3 fields, the header has 2");
    std::ofstream(f, std::ios::trunc) << "a,b\n";
    EXPECT_EQ(error_of(f, {"a", "b"}), at + "1: no data rows");
    EXPECT_EQ(error_of(t.path() / "none.csv", {"a"}),
              "config error: " + (t.path() / "none.csv").string() + ": cannot open file");
}

// Every form C's strtod reads in the C locale, whole field: decimal and hexadecimal (0x1e = 30, 0x1.8p1 = 1.5 * 2 =
// 3), with an optional sign; a second sign, a bare prefix or trailing characters are not numbers.
TEST(CsvTable, NumbersInEveryStrtodForm) {
    test::TempDir t;
    const fs::path f = t.path() / "n.csv";
    std::ofstream(f) << "a,b,c,d,e,f\n0x1e,-0X1.8p1,+.5,2e-3,-0x0.1,0X10P-4\n";
    const CsvTable table = read_csv(f, {"a", "b", "c", "d", "e", "f"});
    EXPECT_EQ(table.at(0, 0), 30.0);
    EXPECT_EQ(table.at(0, 1), -3.0);
    EXPECT_EQ(table.at(0, 2), 0.5);
    EXPECT_EQ(table.at(0, 3), 0.002);
    EXPECT_EQ(table.at(0, 4), -0.0625);
    EXPECT_EQ(table.at(0, 5), 1.0);
    const std::string at = "config error: " + f.string() + ":2: column 'a': '";
    for (const std::string bad : {"0x", "--1", "+-1", "0x-1", "0x+1", "1e", "0x1g", "x1", "1.5 2"}) {
        std::ofstream(f, std::ios::trunc) << "a\n" << bad << "\n";
        EXPECT_EQ(error_of(f, {"a"}), at + bad + "' is not a number") << bad;
    }
}

}  // namespace
}  // namespace gdnav::io::flight_log
