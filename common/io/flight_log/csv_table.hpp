#pragma once
// A minimal reader and writer of numeric CSV files (docs/replay.md): a header row of column names, then rows of
// numbers separated by commas (spaces around fields ignored). Lines starting with '#' and empty lines are skipped.
// Every error is one ConfigError line "FILE:LINE: ..." naming the column where there is one.
#include <cstdio>
#include <filesystem>
#include <string>
#include <vector>

namespace gdnav::io::flight_log {

// Throws the one-line ConfigError "config error: WHERE: WHAT" of a flight log's files.
[[noreturn]] void input_error(const std::string& where, const std::string& what);

// A time in those messages: fixed notation, 6 decimals ("12.340000").
std::string fmt_t(double t_s);

struct CsvTable {
    std::string file;
    std::vector<std::string> columns;  // in the order requested from read_csv
    std::vector<double> values;        // row-major, columns.size() per row
    std::vector<std::size_t> lines;    // source line (1-based) of each row
    [[nodiscard]] std::size_t rows() const { return lines.size(); }
    [[nodiscard]] double at(std::size_t row, std::size_t col) const { return values[row * columns.size() + col]; }
    [[nodiscard]] const double* row(std::size_t r) const { return &values[r * columns.size()]; }
};

// Reads `path`, whose header must hold exactly `columns` (any order). Values must be finite numbers.
CsvTable read_csv(const std::filesystem::path& path, const std::vector<std::string>& columns);

// Writes rows of doubles with 17 significant digits (exact round trip).
class CsvWriter {
public:
    CsvWriter(const std::filesystem::path& path, const std::vector<std::string>& columns);
    ~CsvWriter();
    CsvWriter(const CsvWriter&) = delete;
    CsvWriter& operator=(const CsvWriter&) = delete;
    void row(const std::vector<double>& values);
    void close();

private:
    std::filesystem::path path_;
    std::FILE* f_{nullptr};
    std::size_t columns_{0};
};

}  // namespace gdnav::io::flight_log
