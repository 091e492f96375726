#include "io/run_series/series_columns.hpp"

#include "framework/msg_eigen.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

namespace gdnav::io::run_series {

namespace {
constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();

// Offsets from the origin with the origin's radii (and the given altitude).
void offsets(double lat, double lon, double h, const Origin& o, double& north, double& east) {
    north = (lat - o.lat_rad) * (o.radii.m_m + h);
    east = math::wrap_pi(lon - o.lon_rad) * (o.radii.n_m + h) * std::cos(lat);
}

// The navigation state from the messages that carry its parts (the truth carries all of them).
template <class Air, class Att, class Pos>
metrics::NavState nav_state(const Air& a, const Att& q, const Pos& p) {
    metrics::NavState s;
    s.lat_rad = p.lat_rad();
    s.lon_rad = p.lon_rad();
    s.h_m = p.h_m();
    s.v_n_mps = framework::to_vec3(p.v_n_mps());
    s.q_nb = framework::to_quat(q.q_nb());
    s.tas_mps = a.tas_mps();
    s.aoa_rad = a.aoa_rad();
    s.aos_rad = a.aos_rad();
    s.dT_K = a.dT_K();
    return s;
}
}  // namespace

std::vector<std::string> truth_columns() {
    return {"t_s",    "lat_rad", "lon_rad", "h_m",        "vn_mps",     "ve_mps",     "vd_mps",  "yaw_rad",
            "pitch_rad", "bank_rad", "tas_mps", "aoa_rad", "aos_rad",   "dT_K",       "dp_Pa",   "Hp_m",
            "T_K",    "wind_n_mps", "wind_e_mps", "wind_d_mps", "north_m", "east_m",     "dist_m"};
}

std::vector<std::string> estimate_columns() {
    return {"t_s",    "lat_rad", "lon_rad", "h_m",        "vn_mps",     "ve_mps",     "vd_mps",  "yaw_rad",
            "pitch_rad", "bank_rad", "tas_mps", "aoa_rad", "aos_rad",   "dT_K",       "Hp_m",    "T_K",
            "wind_n_mps", "wind_e_mps", "wind_d_mps", "dp_Pa", "gnss_denied", "north_m", "east_m"};
}

std::vector<std::string> error_columns() {
    return {"t_s",    "yaw_rad", "pitch_rad", "bank_rad", "rot_rad", "tas_mps", "aoa_rad", "aos_rad", "dT_K",
            "h_m",    "vn_mps",  "ve_mps",    "vd_mps",   "north_m", "east_m",  "hor_m",   "cross_m", "along_m"};
}

std::vector<std::string> gnss_columns() { return {"t_s", "lat_rad", "lon_rad", "h_m", "vn_mps", "ve_mps", "vd_mps"}; }

metrics::NavState truth_state(const msg::Truth& t) { return nav_state(t, t, t); }

metrics::NavState estimate_state(const msg::AirDataEstimate& a, const msg::AttitudeEstimate& q,
                                 const msg::PositionEstimate& p) {
    return nav_state(a, q, p);
}

void fill_truth_row(double* r, double t_s, const msg::Truth& t, const Origin& o, double dist_m) {
    const auto& v = t.v_n_mps();
    const auto& e = t.euler_rad();
    const auto& w = t.wind_n_mps();
    double north = 0.0, east = 0.0;
    offsets(t.lat_rad(), t.lon_rad(), t.h_m(), o, north, east);
    const double row[kTruthColumns] = {t_s,      t.lat_rad(), t.lon_rad(), t.h_m(),   v[0],      v[1],   v[2],
                                       e[0],     e[1],        e[2],        t.tas_mps(), t.aoa_rad(), t.aos_rad(),
                                       t.dT_K(), t.dp_Pa(),   t.Hp_m(),    t.T_K(),   w[0],      w[1],   w[2],
                                       north,    east,        dist_m};
    std::copy(row, row + kTruthColumns, r);
}

void fill_estimate_row(double* r, double t_s, const msg::AirDataEstimate* a, const msg::AttitudeEstimate* q,
                       const msg::PositionEstimate* p, const Origin& o, double h_true_m) {
    std::fill(r, r + kEstimateColumns, kNaN);
    r[0] = t_s;
    if (p) {
        const auto& v = p->v_n_mps();
        const auto& w = p->wind_n_mps();
        r[1] = p->lat_rad();
        r[2] = p->lon_rad();
        r[3] = p->h_m();
        r[4] = v[0];
        r[5] = v[1];
        r[6] = v[2];
        r[16] = w[0];
        r[17] = w[1];
        r[18] = w[2];
        r[19] = p->dp_Pa();
        r[20] = p->gnss_denied() ? 1.0 : 0.0;
        // Same altitude as the truth offsets, so north/east differences equal the horizontal errors.
        offsets(p->lat_rad(), p->lon_rad(), h_true_m, o, r[21], r[22]);
    }
    if (q) {
        const math::Euler e = math::euler_from_quat(framework::to_quat(q->q_nb()));
        r[7] = e.yaw_rad;
        r[8] = e.pitch_rad;
        r[9] = e.bank_rad;
    }
    if (a) {
        r[10] = a->tas_mps();
        r[11] = a->aoa_rad();
        r[12] = a->aos_rad();
        r[13] = a->dT_K();
        r[14] = a->Hp_m();
        r[15] = a->T_K();
    }
}

void fill_error_row(double* r, double t_s, const metrics::NavErrors* e) {
    std::fill(r, r + kErrorColumns, kNaN);
    r[0] = t_s;
    if (!e) return;
    const double row[kErrorColumns] = {t_s,        e->yaw_rad,       e->pitch_rad,     e->bank_rad,      e->rot_rad,
                                       e->tas_mps, e->aoa_rad,       e->aos_rad,       e->dT_K,          e->h_m,
                                       e->v_n_mps.x(), e->v_n_mps.y(), e->v_n_mps.z(), e->north_m,       e->east_m,
                                       e->hor_m,   e->cross_m,       e->along_m};
    std::copy(row, row + kErrorColumns, r);
}

void fill_gnss_row(double* r, double t_s, const msg::GnssSample& g) {
    const auto& v = g.v_n_mps();
    const double row[kGnssColumns] = {t_s, g.lat_rad(), g.lon_rad(), g.h_m(), v[0], v[1], v[2]};
    std::copy(row, row + kGnssColumns, r);
}

}  // namespace gdnav::io::run_series
