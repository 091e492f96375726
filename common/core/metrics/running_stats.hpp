#pragma once
// Online statistics of one error signal x_1 .. x_n, updated sample by sample, as the reference's per-run metrics
// (docs/montecarlo.md, "nav_recorder: errors, online metrics and files"):
//   mean  = (1/n) sum x_i
//   std   = sqrt((1/n) sum (x_i - mean)^2)        population std (divides by n, as the paper)
//   smax  = the x_i of largest |x_i|, sign kept    (the first one on ties)
//   last  = x_n                                    (the "final value" of a run)
// Mean and std use Welford's update (m_i = m_{i-1} + (x_i - m_{i-1})/i, M2_i = M2_{i-1} + (x_i - m_{i-1})(x_i - m_i)),
// which stays accurate when |mean| >> std. No allocation; the results are a pure function of the sample sequence.
#include <cstdint>

namespace gdnav::core::metrics {

class RunningStats {
public:
    void add(double x);
    [[nodiscard]] std::uint64_t count() const { return n_; }
    [[nodiscard]] bool empty() const { return n_ == 0; }
    // All four are NaN while empty.
    [[nodiscard]] double mean() const;
    [[nodiscard]] double std() const;
    [[nodiscard]] double smax() const;
    [[nodiscard]] double last() const;

private:
    std::uint64_t n_{0};
    double mean_{0.0};
    double m2_{0.0};
    double smax_{0.0};
    double last_{0.0};
};

}  // namespace gdnav::core::metrics
namespace gdnav { namespace metrics = core::metrics; }  // the short name (docs/architecture.md, "Namespaces")
