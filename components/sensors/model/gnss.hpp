#pragma once
// GNSS receiver (docs/sensors.md, "GNSS"). Called every sensor step k (t = t0 + k dt); a fix
// is produced only on fix epochs, decided on the integer step index alone (no floating time comparison):
//
//   fix epoch:  k mod n_fix == 0  and  k <= k_loss,     n_fix = round(fix_period / dt)
//               k_loss = floor((t_GNSS - t0) / dt + 1e-6)   (t_GNSS exactly on a step counts as that step),
//               no k_loss when no loss time is configured; no fix at all when t_GNSS < t0.
//   fix j = k / n_fix:
//     v~_n = v_n + sigma_vel nu_v                                   white per fix
//     e_n  = (sigma_hor nu_1, sigma_hor nu_2, sigma_ver nu_3) + sigma_iono I(j)
//     (lat, lon, h)~ = the point at NED offset e_n from the true (lat, lon, h) (GeographicLib LocalCartesian,
//     WGS84), i.e. lat~ ~ lat + e_N/(M+h), lon~ ~ lon + e_E/((N+h) cos lat), h~ = h - e_D.
//   Ionospheric state I, per axis, in walk steps: nodes W_0 = iono_initial N(0,1), W_{b+1} = soft-banded walk step
//   of W_b (BandedRandomWalk, +-iono_band, not hard: W_0 may lie outside the band and is pulled back), one node
//   per U = iono_update_fixes fixes, and LINEAR INTERPOLATION between nodes:
//       I(j) = W_b + (W_{b+1} - W_b) (j mod U) / U,   b = j / U.
//   The reference intends exactly this but divides integers, so its I is piecewise constant (W_b for U fixes, then
//   a jump of one walk step). The interpolated walk has the same nodes, so the same slow error statistics
//   (initial sigma 8 m, steps of 0.16 m per minute), without the artificial once-a-minute jumps a filter would
//   see as a position step.
// Between fix epochs and after the loss the output repeats the last fix with fix_valid = false.
// Streams: children "vel", "pos" (per fix) and "iono" (initial state and walk) of the group stream's child "gnss".
// k must not decrease between calls (the ionospheric walk only moves forward).
#include <cstdint>
#include <optional>

#include "random/stream.hpp"
#include "sensors/model/banded_walk.hpp"
#include "sensors/model/sensor_io.hpp"
#include "sensors/model/suite.hpp"

namespace gdnav::sensors {

class GnssReceiver {
public:
    void configure(const GnssParams& params, rnd::Stream stream);
    GnssMeasurement measure(std::uint64_t k, double t_s, const GnssTruth& truth);

    [[nodiscard]] bool is_fix_epoch(std::uint64_t k) const;
    [[nodiscard]] std::uint64_t steps_per_fix() const { return steps_per_fix_; }
    // Last step with a fix; nullopt when signals are never lost. has_fixes() is false when t_GNSS < t0.
    [[nodiscard]] std::optional<std::uint64_t> last_fix_step() const { return last_fix_step_; }
    [[nodiscard]] bool has_fixes() const { return has_fixes_; }
    [[nodiscard]] const GnssParams& params() const { return params_; }

private:
    Vec3 iono_error_m(std::uint64_t fix_index);

    GnssParams params_;
    std::uint64_t steps_per_fix_{100};
    std::optional<std::uint64_t> last_fix_step_;
    bool has_fixes_{true};
    rnd::Stream vel_, pos_, iono_;
    BandedRandomWalk walk_[3];
    Vec3 node_prev_{Vec3::Zero()};
    Vec3 node_next_{Vec3::Zero()};
    std::uint64_t block_{0};
    GnssMeasurement last_;
};

}  // namespace gdnav::sensors
