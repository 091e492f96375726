#pragma once
// The random start and end times of a ramp, shared by the wind ramp and the atmospheric offsets ramp (reference
// sections 2.1 and 3.1). N ~ N(0, 1):
//   t_ini = t_ini_mean + s_t N, redrawn until >= t_min
//   t_end = t_ini + dt_mean + s_t N, redrawn until >= t_ini + min_gap   (each ramp states its min_gap)
// The redraw loops terminate with probability one only if s_t > 0 and dt_mean >= 0 (valid()).
#include "random/stream.hpp"

namespace gdnav::core::rnd {

struct RampTimesSpec {
    double t_ini_mean_s{400.0};
    double dt_mean_s{1200.0};
    double sigma_t_s{600.0};
    double t_min_s{50.0};

    [[nodiscard]] bool valid() const { return sigma_t_s > 0.0 && dt_mean_s >= 0.0; }

    double draw_start_s(Stream& s) const {
        double t = 0.0;
        do {
            t = t_ini_mean_s + sigma_t_s * s.normal();
        } while (t < t_min_s);
        return t;
    }

    double draw_end_s(Stream& s, double t_ini_s, double min_gap_s) const {
        double t = 0.0;
        do {
            t = t_ini_s + dt_mean_s + sigma_t_s * s.normal();
        } while (t < t_ini_s + min_gap_s);
        return t;
    }
};

}  // namespace gdnav::core::rnd
namespace gdnav { namespace rnd = core::rnd; }  // the short name (docs/architecture.md, "Namespaces")
