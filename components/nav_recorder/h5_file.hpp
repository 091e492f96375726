#pragma once
// A small RAII wrapper of the HDF5 C API (Debian libhdf5, no C++ binding) for what nav_recorder writes:
// extendible one-dimensional tables whose rows are compounds of named IEEE-754 little-endian doubles (h5py reads
// them as numpy structured arrays, MATLAB's h5read as a struct of column vectors), scalar attributes and one
// fixed-size metrics table with a string column.
//
// Crash safety: rows are appended only by append() and made durable by flush() (H5Fflush of the whole file). The
// caller buffers rows in memory and calls append + flush together, so between flushes the library does no I/O and
// the file on disk is the consistent state of the last flush: a SIGKILLed writer leaves a readable file.
#include <hdf5.h>

#include <cstdint>
#include <filesystem>
#include <string>
#include <vector>

namespace gdnav::nav_recorder {

class H5File {
public:
    // Creates (truncates) `path`. Every call throws files::WriteError (the file and the OS error) when the operating
    // system refused a write, std::runtime_error with the HDF5 message on any other failure.
    explicit H5File(const std::filesystem::path& path);
    ~H5File();
    H5File(const H5File&) = delete;
    H5File& operator=(const H5File&) = delete;

    // A table of doubles named `columns`, chunked by `chunk_rows`, deflate level 0 (none) .. 9 (with shuffle).
    int add_table(const std::string& name, const std::vector<std::string>& columns, std::size_t chunk_rows,
                  int deflate_level);
    // Appends `rows` rows, row-major (rows x columns doubles).
    void append(int table, const double* data, std::size_t rows);
    [[nodiscard]] std::uint64_t rows(int table) const { return tables_.at(static_cast<std::size_t>(table)).rows; }

    // Root attributes (created or overwritten).
    void set_attribute(const std::string& name, double value);
    void set_attribute(const std::string& name, std::int64_t value);
    void set_attribute(const std::string& name, const std::string& value);
    // Attribute on a table.
    void set_table_attribute(int table, const std::string& name, const std::string& value);

    struct MetricsRow {
        std::string name;
        std::uint64_t n;
        double mean, std, max, final;
    };
    // Dataset `name` of rows {name (fixed string), n, mean, std, max, final}.
    void write_metrics(const std::string& name, const std::vector<MetricsRow>& rows);

    void flush();
    void close();
    [[nodiscard]] bool open() const { return file_ >= 0; }

private:
    struct Table {
        hid_t dataset{-1};
        hid_t mem_type{-1};
        std::size_t columns{0};
        std::uint64_t rows{0};
    };
    void attribute(hid_t loc, const std::string& name, hid_t type, const void* value);
    hid_t file_{-1};
    std::vector<Table> tables_;
    std::string path_;
};

}  // namespace gdnav::nav_recorder
