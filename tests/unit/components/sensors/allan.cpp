#include "allan.hpp"

#include <cmath>
#include <stdexcept>

namespace gdnav::sensors::test {

double allan_deviation(const std::vector<double>& rate, double tau0_s, std::size_t m) {
    const std::size_t n = rate.size();
    if (m == 0 || 2 * m > n) throw std::invalid_argument("allan_deviation: cluster size out of range");
    // Phase with long-double accumulation: the sums of millions of samples must not lose the small differences.
    std::vector<long double> theta(n + 1, 0.0L);
    for (std::size_t i = 0; i < n; ++i) theta[i + 1] = theta[i] + static_cast<long double>(rate[i]) * tau0_s;
    long double acc = 0.0L;
    const std::size_t terms = n + 1 - 2 * m;
    for (std::size_t j = 0; j < terms; ++j) {
        const long double d = theta[j + 2 * m] - 2.0L * theta[j + m] + theta[j];
        acc += d * d;
    }
    const long double tau = static_cast<long double>(m) * tau0_s;
    return static_cast<double>(std::sqrt(acc / (2.0L * tau * tau * static_cast<long double>(terms))));
}

}  // namespace gdnav::sensors::test
