#include "earth/magnetic.hpp"

namespace gdnav::core::earth {

MagneticModel::MagneticModel(const MagneticCorners& corners) : c_(corners), valid_(true) {}

MagneticModel MagneticModel::from_config(const config::Config& cfg) {
    using config::Range;
    MagneticCorners c;
    c.lat_min_rad = cfg.get_angle_deg("lat_min_deg", Range{-90.0, 90.0});
    c.lat_max_rad = cfg.get_angle_deg("lat_max_deg", Range{-90.0, 90.0});
    c.lon_min_rad = cfg.get_angle_deg("lon_min_deg", Range{-180.0, 360.0});
    c.lon_max_rad = cfg.get_angle_deg("lon_max_deg", Range{-180.0, 360.0});
    if (!(c.lat_max_rad > c.lat_min_rad)) cfg.fail("lat_max_deg", "must be greater than lat_min_deg");
    const double dlon = math::wrap_2pi(c.lon_max_rad - c.lon_min_rad);
    if (!(dlon > 0.0 && dlon < math::kPi)) cfg.fail("lon_max_deg", "must lie east of lon_min_deg (by less than 180)");
    const Range field{-1e5, 1e5};
    c.b_ll_nT = cfg.get_vec3("b_n_lat_min_lon_min_nT", field);
    c.b_lr_nT = cfg.get_vec3("b_n_lat_min_lon_max_nT", field);
    c.b_ul_nT = cfg.get_vec3("b_n_lat_max_lon_min_nT", field);
    c.b_ur_nT = cfg.get_vec3("b_n_lat_max_lon_max_nT", field);
    return MagneticModel(c);
}

MagneticModel MagneticModel::load(const std::filesystem::path& file) {
    const config::Config cfg = config::Config::load(file);
    MagneticModel m = from_config(cfg);
    cfg.finish();
    return m;
}

Vec3 MagneticModel::field_n_nT(double lat_rad, double lon_rad) const {
    const double r1 = (lat_rad - c_.lat_min_rad) / (c_.lat_max_rad - c_.lat_min_rad);
    const double r2 = math::wrap_pi(lon_rad - c_.lon_min_rad) / math::wrap_2pi(c_.lon_max_rad - c_.lon_min_rad);
    return (1.0 - r2) * (c_.b_ll_nT + r1 * (c_.b_ul_nT - c_.b_ll_nT)) +
           r2 * (c_.b_lr_nT + r1 * (c_.b_ur_nT - c_.b_lr_nT));
}

}  // namespace gdnav::core::earth
