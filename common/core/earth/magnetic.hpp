#pragma once
// Model and true Earth magnetic field in NED [nT].
//
// Model field: no time or altitude dependence; bilinear interpolation in (lat, lon) between four corner values
// (the reference's "Wisconsin" square, NOAA IGRF/WMM calculator at 3000 m on 2018-01-01), linear extrapolation
// outside the square:
//   r1 = (lat - lat_min) / (lat_max - lat_min),  r2 = wrap_pi(lon - lon_min) / (lon_max - lon_min)
//   B  = (1 - r2) [B_ll + r1 (B_ul - B_ll)] + r2 [B_lr + r1 (B_ur - B_lr)]
// (l = lat_min row "lower", u = lat_max row "upper", first letter latitude, second l = lon_min, r = lon_max).
// A constant field is four equal corners. Corner values live in config/earth/*.yaml.
// True field: B_true = B_model + eps, with eps the constant per-run NED deviation of EarthTruthParams.
#include <filesystem>

#include "config/config.hpp"
#include "earth/wgs84.hpp"

namespace gdnav::core::earth {

struct MagneticCorners {
    double lat_min_rad{0.0};
    double lat_max_rad{0.0};
    double lon_min_rad{0.0};
    double lon_max_rad{0.0};
    Vec3 b_ll_nT{Vec3::Zero()};  // (lat_min, lon_min)
    Vec3 b_lr_nT{Vec3::Zero()};  // (lat_min, lon_max)
    Vec3 b_ul_nT{Vec3::Zero()};  // (lat_max, lon_min)
    Vec3 b_ur_nT{Vec3::Zero()};  // (lat_max, lon_max)
};

class MagneticModel {
public:
    MagneticModel() = default;  // unset: valid() == false
    explicit MagneticModel(const MagneticCorners& corners);
    // Reads the keys of a magnetic model file (see config/earth/magnetic_wisconsin.yaml). Does not call finish().
    static MagneticModel from_config(const config::Config& cfg);
    // Loads and fully validates a file (unknown keys rejected).
    static MagneticModel load(const std::filesystem::path& file);

    [[nodiscard]] bool valid() const { return valid_; }
    [[nodiscard]] Vec3 field_n_nT(double lat_rad, double lon_rad) const;
    [[nodiscard]] Vec3 true_field_n_nT(double lat_rad, double lon_rad, const Vec3& mag_dev_n_nT) const {
        return field_n_nT(lat_rad, lon_rad) + mag_dev_n_nT;
    }
    [[nodiscard]] const MagneticCorners& corners() const { return c_; }

private:
    MagneticCorners c_{};
    bool valid_{false};
};

}  // namespace gdnav::core::earth
namespace gdnav { namespace earth = core::earth; }  // the short name (docs/architecture.md, "Namespaces")
