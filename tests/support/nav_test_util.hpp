#pragma once
// Helpers shared by the EKF toolkit and navigation tests: row-wise matrix comparison, random vectors, source paths.
#include <algorithm>
#include <cmath>
#include <string>

#include <Eigen/Core>

#include "random/stream.hpp"

namespace gdnav::nav::test {

// Largest row-wise relative error: max_i max_j |A_ij - B_ij| / max_j |B_ij| (rows of B that are all zero are
// compared in absolute terms). Row scaling keeps rows of very different magnitude (e.g. rad/s vs m/s^2) honest.
template <typename DA, typename DB>
double rowwise_relative_error(const Eigen::MatrixBase<DA>& a, const Eigen::MatrixBase<DB>& b) {
    double worst = 0.0;
    for (int i = 0; i < b.rows(); ++i) {
        const double scale = b.row(i).cwiseAbs().maxCoeff();
        const double err = (a.row(i) - b.row(i)).cwiseAbs().maxCoeff();
        worst = std::max(worst, scale > 0.0 ? err / scale : err);
    }
    return worst;
}

inline Eigen::Vector3d random_vec(rnd::Stream& s, double scale) { return scale * s.normal3(); }

#ifdef GDNAV_SOURCE_DIR
inline std::string source_path(const std::string& rel) { return std::string(GDNAV_SOURCE_DIR) + "/" + rel; }
#endif

}  // namespace gdnav::nav::test
