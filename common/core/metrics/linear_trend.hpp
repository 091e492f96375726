#pragma once
// Online least-squares line y = a + b t through samples (t_i, y_i), updated sample by sample (co-moments with
// Welford's centred update, so it stays accurate for t ~ 1e3 s and small slopes):
//   slope b = S_ty / S_tt,   r2 = S_ty^2 / (S_tt S_yy)   (coefficient of determination of the fit)
// with S_tt = sum (t - t_mean)^2, S_yy likewise, S_ty = sum (t - t_mean)(y - y_mean). Used for the attitude drift
// (slope of the attitude error after a settling time) and the growth of the horizontal error after t_GNSS.
#include <cstdint>

namespace gdnav::core::metrics {

class LinearTrend {
public:
    void add(double t, double y);
    [[nodiscard]] std::uint64_t count() const { return n_; }
    // NaN with fewer than two samples (or all t equal); r2 is NaN also when all y are equal.
    [[nodiscard]] double slope() const;
    [[nodiscard]] double r2() const;

private:
    std::uint64_t n_{0};
    double t_mean_{0.0}, y_mean_{0.0};
    double s_tt_{0.0}, s_yy_{0.0}, s_ty_{0.0};
};

}  // namespace gdnav::core::metrics
namespace gdnav { namespace metrics = core::metrics; }  // the short name (docs/architecture.md, "Namespaces")
