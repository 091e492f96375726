#include "io/flight_log/csv_table.hpp"

#include <cerrno>
#include <charconv>
#include <cmath>
#include <fstream>
#include <map>
#include <stdexcept>

#include "config/config.hpp"
#include "files/write_error.hpp"

namespace gdnav::io::flight_log {

void input_error(const std::string& where, const std::string& what) {
    throw config::ConfigError("config error: " + where + ": " + what);
}

std::string fmt_t(double t_s) {
    char b[48];
    std::snprintf(b, sizeof(b), "%.6f", t_s);
    return b;
}

namespace {

std::string trim(const std::string& s) {
    const auto b = s.find_first_not_of(" \t\r");
    if (b == std::string::npos) return {};
    const auto e = s.find_last_not_of(" \t\r");
    return s.substr(b, e - b + 1);
}

std::vector<std::string> split(const std::string& line) {
    std::vector<std::string> out;
    std::size_t start = 0;
    while (true) {
        const auto comma = line.find(',', start);
        out.push_back(trim(line.substr(start, comma == std::string::npos ? std::string::npos : comma - start)));
        if (comma == std::string::npos) break;
        start = comma + 1;
    }
    return out;
}

// A number as C's strtod reads it in the C locale ('.' decimal point), whole field: an optional sign, then a
// decimal form (12, -1.5, .5, 2e-3) or a hexadecimal one (0x1e, -0X1.8p1). from_chars, not strtod: strtod follows
// the process's locale. NaN and infinity are parsed here and refused by the caller.
bool parse_number(const std::string& f, double& v) {
    const char* b = f.data();
    const char* e = f.data() + f.size();
    const bool negative = b != e && *b == '-';
    if (b != e && (*b == '+' || *b == '-')) ++b;
    if (b == e || *b == '+' || *b == '-') return false;  // from_chars would take a second sign
    auto format = std::chars_format::general;
    if (e - b > 2 && b[0] == '0' && (b[1] == 'x' || b[1] == 'X')) {
        b += 2;
        if (*b == '+' || *b == '-') return false;
        format = std::chars_format::hex;
    }
    const auto r = std::from_chars(b, e, v, format);
    if (r.ec != std::errc() || r.ptr != e) return false;
    if (negative) v = -v;
    return true;
}

std::string join(const std::vector<std::string>& v) {
    std::string s;
    for (const auto& x : v) s += (s.empty() ? "" : ", ") + x;
    return s;
}

}  // namespace

CsvTable read_csv(const std::filesystem::path& path, const std::vector<std::string>& columns) {
    CsvTable t;
    t.file = path.string();
    t.columns = columns;
    auto fail = [&](std::size_t line, const std::string& what) {
        throw config::ConfigError("config error: " + t.file + ":" + std::to_string(line) + ": " + what);
    };
    std::ifstream in(path);
    if (!in) throw config::ConfigError("config error: " + t.file + ": cannot open file");
    std::vector<std::size_t> slot;  // file field index -> requested column index
    bool header = false;
    std::string line;
    std::size_t n = 0;
    while (std::getline(in, line)) {
        ++n;
        const std::string s = trim(line);
        if (s.empty() || s[0] == '#') continue;
        const auto fields = split(s);
        if (!header) {
            header = true;
            std::map<std::string, std::size_t> want;
            for (std::size_t i = 0; i < columns.size(); ++i) want[columns[i]] = i;
            std::vector<bool> found(columns.size(), false);
            for (const auto& f : fields) {
                auto it = want.find(f);
                if (it == want.end()) fail(n, "unknown column '" + f + "' (expected: " + join(columns) + ")");
                if (found[it->second]) fail(n, "column '" + f + "' appears twice");
                found[it->second] = true;
                slot.push_back(it->second);
            }
            for (std::size_t i = 0; i < columns.size(); ++i)
                if (!found[i]) fail(n, "missing column '" + columns[i] + "'");
            continue;
        }
        if (fields.size() != slot.size())
            fail(n, std::to_string(fields.size()) + " fields, the header has " + std::to_string(slot.size()));
        const std::size_t base = t.values.size();
        t.values.resize(base + columns.size());
        for (std::size_t i = 0; i < fields.size(); ++i) {
            const std::string& f = fields[i];
            const std::string& col = columns[slot[i]];
            double v = 0.0;
            if (!parse_number(f, v)) fail(n, "column '" + col + "': '" + f + "' is not a number");
            if (!std::isfinite(v)) fail(n, "column '" + col + "': " + f + " (NaN and infinite values are not allowed)");
            t.values[base + slot[i]] = v;
        }
        t.lines.push_back(n);
    }
    if (in.bad()) throw config::ConfigError("config error: " + t.file + ": read error");
    if (!header) fail(n, "no header row (expected: " + join(columns) + ")");
    if (t.rows() == 0) fail(n, "no data rows");
    return t;
}

CsvWriter::CsvWriter(const std::filesystem::path& path, const std::vector<std::string>& columns)
    : path_(path), f_(std::fopen(path.c_str(), "w")), columns_(columns.size()) {
    if (!f_) throw config::ConfigError("config error: " + path.string() + ": cannot write");
    std::string header;
    for (const auto& c : columns) header += (header.empty() ? "" : ",") + c;
    std::fprintf(f_, "%s\n", header.c_str());
}

CsvWriter::~CsvWriter() {
    if (f_) std::fclose(f_);
}

void CsvWriter::row(const std::vector<double>& values) {
    if (values.size() != columns_) throw std::logic_error("CsvWriter: row size differs from the header's");
    for (std::size_t i = 0; i < values.size(); ++i) std::fprintf(f_, i ? ",%.17g" : "%.17g", values[i]);
    std::fputc('\n', f_);
}

void CsvWriter::close() {
    const bool bad = std::ferror(f_) != 0;
    const bool closed = std::fclose(f_) == 0;
    f_ = nullptr;
    if (bad || !closed) files::throw_write_error(path_, errno ? errno : EIO);
}

}  // namespace gdnav::io::flight_log
