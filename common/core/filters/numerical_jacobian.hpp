#pragma once
// Central-difference Jacobian for tests: J(:, j) = (f(x + h_j e_j) - f(x - h_j e_j)) / (2 h_j),
// with h_j = rel_step * max(|x_j|, abs_floor). Truncation error O(h^2 f'''), round-off O(eps |f| / h);
// rel_step ~ 1e-5..1e-6 balances both for smooth functions of O(1) curvature.
#include <algorithm>
#include <cmath>

#include <Eigen/Core>

namespace gdnav::core::filters {

template <int M, int N, typename F>
Eigen::Matrix<double, M, N> numerical_jacobian(F&& f, const Eigen::Matrix<double, N, 1>& x, double rel_step = 1e-6,
                                               double abs_floor = 1.0) {
    Eigen::Matrix<double, M, N> j;
    for (int c = 0; c < N; ++c) {
        const double h = rel_step * std::max(std::abs(x(c)), abs_floor);
        Eigen::Matrix<double, N, 1> xp = x, xm = x;
        xp(c) += h;
        xm(c) -= h;
        const Eigen::Matrix<double, M, 1> fp = f(xp);
        const Eigen::Matrix<double, M, 1> fm = f(xm);
        j.col(c) = (fp - fm) / (xp(c) - xm(c));
    }
    return j;
}

// Largest element-wise error |A - B| relative to max(|B|_max, floor): the acceptance metric of the Jacobian tests.
template <typename DA, typename DB>
double relative_error(const Eigen::MatrixBase<DA>& a, const Eigen::MatrixBase<DB>& b, double floor = 1e-12) {
    const double scale = std::max(b.cwiseAbs().maxCoeff(), floor);
    return (a - b).cwiseAbs().maxCoeff() / scale;
}

}  // namespace gdnav::core::filters
namespace gdnav { namespace filters = core::filters; }  // the short name (docs/architecture.md, "Namespaces")
