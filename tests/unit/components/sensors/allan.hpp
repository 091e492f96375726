#pragma once
// Test support: overlapping Allan deviation (IEEE Std 952 / NIST SP 1065 eq. for the overlapping estimator).
// For N rate samples y_i taken every tau0, the "phase" theta_j = tau0 * sum_{i<j} y_i (theta_0 = 0), and for
// cluster size m (tau = m tau0):
//     AVAR(tau) = sum_{j=0}^{N-2m} (theta_{j+2m} - 2 theta_{j+m} + theta_j)^2 / (2 tau^2 (N - 2m + 1))
// Known results used by the tests: white rate noise of density sigma_v -> ADEV = sigma_v / sqrt(tau);
// rate random walk of density sigma_u -> ADEV = sigma_u sqrt(tau / 3).
#include <cstddef>
#include <vector>

namespace gdnav::sensors::test {

double allan_deviation(const std::vector<double>& rate, double tau0_s, std::size_t m);

}  // namespace gdnav::sensors::test
