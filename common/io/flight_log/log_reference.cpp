#include "io/flight_log/log_reference.hpp"

#include <algorithm>
#include <cmath>
#include <fstream>
#include <limits>

#include "config/config.hpp"
#include "io/flight_log/csv_table.hpp"
#include "math/rotation.hpp"
#include "msgs/messages.hpp"

namespace gdnav::io::flight_log {

namespace fs = std::filesystem;

namespace {

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();

// The column names of the header row (the first line that is neither empty nor a '#' comment).
std::vector<std::string> header_of(const fs::path& file) {
    std::ifstream in(file);
    if (!in) input_error(file.string(), "cannot open file (--reference)");
    std::string line;
    while (std::getline(in, line)) {
        auto trim = [](const std::string& s) {
            const auto b = s.find_first_not_of(" \t\r");
            return b == std::string::npos ? std::string() : s.substr(b, s.find_last_not_of(" \t\r") - b + 1);
        };
        const std::string s = trim(line);
        if (s.empty() || s[0] == '#') continue;
        std::vector<std::string> names;
        std::size_t start = 0;
        for (std::size_t comma; (comma = s.find(',', start)) != std::string::npos; start = comma + 1)
            names.push_back(trim(s.substr(start, comma - start)));
        names.push_back(trim(s.substr(start)));
        return names;
    }
    input_error(file.string(), "no header row (--reference)");
}

// Which of the accepted column sets the header uses; the columns to read, in the order the conversion expects.
struct Layout {
    bool lat_lon_deg{false};
    enum class Attitude { quaternion, euler_rad, euler_deg } attitude{Attitude::quaternion};
    std::array<bool, 4> air{};  // tas_mps, aoa_rad, aos_rad, dT_K present
    std::vector<std::string> columns;
};

constexpr std::array<const char*, 4> kAir{"tas_mps", "aoa_rad", "aos_rad", "dT_K"};

Layout layout_of(const std::vector<std::string>& header) {
    auto has = [&](const std::string& c) { return std::find(header.begin(), header.end(), c) != header.end(); };
    Layout l;
    l.lat_lon_deg = has("lat_deg") || has("lon_deg");
    const std::string u = l.lat_lon_deg ? "_deg" : "_rad";
    l.columns = {"t_s", "lat" + u, "lon" + u, "h_m", "v_n_mps_0", "v_n_mps_1", "v_n_mps_2"};
    if (has("yaw_deg") || has("pitch_deg") || has("bank_deg")) l.attitude = Layout::Attitude::euler_deg;
    else if (has("yaw_rad") || has("pitch_rad") || has("bank_rad")) l.attitude = Layout::Attitude::euler_rad;
    if (l.attitude == Layout::Attitude::quaternion) {
        for (const char* c : {"q_nb_0", "q_nb_1", "q_nb_2", "q_nb_3"}) l.columns.push_back(c);
    } else {
        const std::string a = l.attitude == Layout::Attitude::euler_deg ? "_deg" : "_rad";
        for (const char* c : {"yaw", "pitch", "bank"}) l.columns.push_back(c + a);
    }
    for (std::size_t i = 0; i < kAir.size(); ++i)
        if ((l.air[i] = has(kAir[i]))) l.columns.push_back(kAir[i]);
    return l;
}

}  // namespace

const std::vector<std::string>& reference_columns() {
    static const std::vector<std::string> c{"t_s",    "lat_rad", "lon_rad", "h_m",     "v_n_mps_0", "v_n_mps_1",
                                            "v_n_mps_2", "q_nb_0", "q_nb_1", "q_nb_2",  "q_nb_3",    "tas_mps",
                                            "aoa_rad", "aos_rad", "dT_K"};
    return c;
}

std::vector<double> reference_row(const msg::Truth& t) {
    const auto& v = t.v_n_mps();
    const auto& q = t.q_nb();
    return {t.stamp().t_s(), t.lat_rad(), t.lon_rad(), t.h_m(), v[0], v[1], v[2], q[0], q[1], q[2], q[3],
            t.tas_mps(), t.aoa_rad(), t.aos_rad(), t.dT_K()};
}

ReferenceTrack::ReferenceTrack(const fs::path& file, const ImportOptions& o, std::uint64_t steps)
    : file_(file.string()), grid_(o) {
    const Layout l = layout_of(header_of(file));
    const CsvTable t = read_csv(file, l.columns);  // exactly these columns, finite numbers
    form_ = std::string("lat/lon in ") + (l.lat_lon_deg ? "deg" : "rad") + ", attitude as " +
            (l.attitude == Layout::Attitude::quaternion ? "q_nb" : l.attitude == Layout::Attitude::euler_deg
                                                                       ? "yaw/pitch/bank in deg"
                                                                       : "yaw/pitch/bank in rad");
    const double scale = l.lat_lon_deg ? math::deg2rad(1.0) : 1.0;
    for (std::size_t r = 0; r < t.rows(); ++r) {
        const double* a = t.row(r);
        const std::string where = t.file + ":" + std::to_string(t.lines[r]);
        if (r > 0 && !(a[0] > t_.back()))
            input_error(where, "column 't_s': " + fmt_t(a[0]) + " s is not after the previous row's " + fmt_t(t_.back()) +
                            " s (times must increase)");
        if (r > 0 && a[0] - t_.back() > o.max_gap_s)
            input_error(where, "column 't_s': gap of " + fmt_t(a[0] - t_.back()) + " s after t = " + fmt_t(t_.back()) +
                            " s (at most " + fmt_t(o.max_gap_s) + " s, --max-gap)");
        math::Quat q;
        if (l.attitude == Layout::Attitude::quaternion) {
            q = math::Quat(a[7], a[8], a[9], a[10]);
            const double n = q.norm();
            if (std::abs(n - 1.0) > 1e-6)
                input_error(where, "columns 'q_nb_0..3': norm " + std::to_string(n) + " is not 1 (a unit quaternion w, x, y, z)");
        } else {
            const double s = l.attitude == Layout::Attitude::euler_deg ? math::deg2rad(1.0) : 1.0;
            q = math::quat_from_euler({a[7] * s, a[8] * s, a[9] * s});
        }
        const std::size_t air0 = l.attitude == Layout::Attitude::quaternion ? 11 : 10;
        std::array<double, 4> air{kNaN, kNaN, kNaN, kNaN};
        for (std::size_t i = 0, c = air0; i < 4; ++i)
            if (l.air[i]) air[i] = a[c++];
        t_.push_back(a[0]);
        lines_.push_back(t.lines[r]);
        const double v[kCols] = {a[1] * scale, a[2] * scale, a[3], a[4], a[5], a[6], q.w(), q.x(), q.y(), q.z(),
                                 air[0], air[1], air[2], air[3]};
        values_.insert(values_.end(), v, v + kCols);
    }
    const double first_s = o.t0_s, last_s = o.t0_s + static_cast<double>(steps - 1) * o.dt_s;
    if (t_.empty() || t_.front() > first_s + kSnapS || t_.back() < last_s - kSnapS)
        input_error(file_, "the reference spans t = " + (t_.empty() ? std::string("nothing") : fmt_t(t_.front()) + " .. " + fmt_t(t_.back()) + " s") +
                        ", the grid t = " + fmt_t(first_s) + " .. " + fmt_t(last_s) +
                        " s: it must cover every step (shorten the grid with --steps)");
}

void ReferenceTrack::fill(std::uint64_t k, msg::Truth& out) {
    const double tk = grid_.t0_s + static_cast<double>(k) * grid_.dt_s;
    while (i_ + 1 < t_.size() && t_[i_ + 1] <= tk) ++i_;
    double v[kCols];
    const double* a = row(i_);
    const bool at_a = std::abs(tk - t_[i_]) <= kSnapS || i_ + 1 == t_.size();
    const bool at_b = !at_a && std::abs(t_[i_ + 1] - tk) <= kSnapS;
    if (at_a || at_b) {
        std::copy(at_a ? a : row(i_ + 1), (at_a ? a : row(i_ + 1)) + kCols, v);
    } else {
        const double* b = row(i_ + 1);
        const double u = (tk - t_[i_]) / (t_[i_ + 1] - t_[i_]);
        for (std::size_t c = 0; c < kCols; ++c) v[c] = a[c] + u * (b[c] - a[c]);
        v[1] = math::wrap_pi(a[1] + u * math::wrap_pi(b[1] - a[1]));
        // Towards the nearer of b and -b (the same rotation), then back to unit length.
        const double dot = a[6] * b[6] + a[7] * b[7] + a[8] * b[8] + a[9] * b[9];
        const double sb = dot < 0.0 ? -1.0 : 1.0;
        for (std::size_t c = 6; c < 10; ++c) v[c] = a[c] + u * (sb * b[c] - a[c]);
        const double n = std::sqrt(v[6] * v[6] + v[7] * v[7] + v[8] * v[8] + v[9] * v[9]);
        for (std::size_t c = 6; c < 10; ++c) v[c] /= n;
    }
    out = msg::Truth();
    // Every field the reference does not define is NaN (no value), not zero.
    auto nan3 = [](std::array<double, 3>& x) { x.fill(kNaN); };
    nan3(out.w_ib_b_rps());
    nan3(out.w_nb_b_rps());
    nan3(out.dw_ib_b_rps2());
    nan3(out.f_ib_b_mps2());
    nan3(out.wind_n_mps());
    nan3(out.turb_b_mps());
    nan3(out.g_n_mps2());
    nan3(out.g_model_n_mps2());
    nan3(out.b_n_nT());
    nan3(out.b_model_n_nT());
    out.controls().fill(kNaN);
    for (double* x : {&out.dp_Pa(), &out.Hp_m(), &out.H_m(), &out.p_Pa(), &out.T_K(), &out.rho_kgpm3(), &out.mass_kg()})
        *x = kNaN;
    out.lat_rad(v[0]);
    out.lon_rad(v[1]);
    out.h_m(v[2]);
    out.v_n_mps({v[3], v[4], v[5]});
    out.q_nb({v[6], v[7], v[8], v[9]});
    const math::Euler e = math::euler_from_quat(math::Quat(v[6], v[7], v[8], v[9]));
    out.euler_rad({e.yaw_rad, e.pitch_rad, e.bank_rad});
    out.tas_mps(v[10]);
    out.aoa_rad(v[11]);
    out.aos_rad(v[12]);
    out.dT_K(v[13]);
}

}  // namespace gdnav::io::flight_log
