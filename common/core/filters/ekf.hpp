#pragma once
// The one EKF toolkit of gdnav: fixed-size Eigen types templated on the state size N and the measurement size M,
// discrete propagation and Joseph-form update. Every navigation filter (air data, attitude, position) uses it.
//
// Discrete model used by all filters (as in the reference; docs/navigation.md, "EKF toolkit"):
//   propagate: A = df/dx at x+(k-1);  Phi = exp(A dt) ~ I + A dt + (A dt)^2/2 + ... (truncated Taylor series);
//              x-(k) = x+(k-1) + dt f(x+(k-1))  (forward Euler on the non-linear f, done by the caller);
//              P-(k) = Phi P+(k-1) Phi^T + Q    (Q is the discrete per-step covariance)
//   update:    S = H P- H^T + R;  K = P- H^T S^-1;  r = y - h(x-);
//              x+ = x- + K r;  P+ = (I - K H) P- (I - K H)^T + K R K^T   (Joseph form, symmetric by construction)
// No heap allocation: all sizes are compile-time. Products use Eigen's coefficient-based lazyProduct, which for
// these small fixed sizes beats the blocked GEMM path (no packing; docs/navigation.md, "EKF toolkit").
#include <Eigen/Cholesky>
#include <Eigen/Dense>

namespace gdnav::core::filters {

template <int N>
using Vec = Eigen::Matrix<double, N, 1>;
template <int N>
using SqMat = Eigen::Matrix<double, N, N>;
template <int M, int N>
using Mat = Eigen::Matrix<double, M, N>;

// Truncated Taylor series of the matrix exponential exp(A dt) with terms up to (A dt)^order / order!.
// order = 1 gives Phi = I + A dt. For the filters here |A dt| < 1e-2, so order 2 differs from exp(A dt) by < 1e-7.
template <int N>
SqMat<N> transition_matrix(const SqMat<N>& a, double dt_s, int order = 2) {
    SqMat<N> phi = SqMat<N>::Identity();
    SqMat<N> term = SqMat<N>::Identity();
    const SqMat<N> adt = a * dt_s;
    for (int i = 1; i <= order; ++i) {
        term = (term.lazyProduct(adt) / static_cast<double>(i)).eval();  // lazy product: avoid aliasing
        phi += term;
    }
    return phi;
}

// Replaces P by its symmetric part (removes round-off asymmetry).
template <int N>
void symmetrize(SqMat<N>& p) {
    const SqMat<N> t = p.transpose();
    p = 0.5 * (p + t);
}

// P <- Phi P Phi^T + Q.
template <int N>
void propagate_covariance(SqMat<N>& p, const SqMat<N>& phi, const SqMat<N>& q) {
    const SqMat<N> tmp = phi * p;
    p = tmp * phi.transpose() + q;
    symmetrize<N>(p);
}

// P <- Phi P Phi^T + diag(q).
template <int N>
void propagate_covariance_diag(SqMat<N>& p, const SqMat<N>& phi, const Vec<N>& q_diag) {
    const SqMat<N> tmp = phi.lazyProduct(p);
    p = tmp.lazyProduct(phi.transpose());
    p.diagonal() += q_diag;
    symmetrize<N>(p);
}

// Covariance propagation when A (hence Phi) differs from the identity only in its leading K x K block:
// Phi = diag(Phi_K, I). With P = [[P_KK, P_KR], [P_RK, P_RR]]:
//   Phi P Phi^T = [[Phi_K P_KK Phi_K^T, Phi_K P_KR], [(Phi_K P_KR)^T, P_RR]],   then + diag(q).
// Identical to propagate_covariance_diag with the full Phi, at a fraction of the cost.
template <int N, int K>
void propagate_covariance_leading_diag(SqMat<N>& p, const SqMat<K>& phi_k, const Vec<N>& q_diag) {
    static_assert(K <= N, "leading block larger than the state");
    const SqMat<K> pk = phi_k.lazyProduct(p.template topLeftCorner<K, K>());
    const SqMat<K> pkk = pk.lazyProduct(phi_k.transpose());
    p.template topLeftCorner<K, K>() = pkk;
    if constexpr (K < N) {
        const Mat<K, N - K> pkr = phi_k.lazyProduct(p.template topRightCorner<K, N - K>());
        p.template topRightCorner<K, N - K>() = pkr;
        p.template bottomLeftCorner<N - K, K>() = pkr.transpose();
    }
    p.diagonal() += q_diag;
    symmetrize<N>(p);
}

// What an update did: innovation r, its covariance S and the normalised innovation squared r^T S^-1 r.
template <int M>
struct UpdateInfo {
    Vec<M> innovation = Vec<M>::Zero();
    SqMat<M> innovation_cov = SqMat<M>::Zero();
    double nis{0.0};
    bool ok{false};  // false if S was not positive definite (then x and P are left unchanged)
};

// Joseph-form EKF update with a given innovation r = y - h(x-), Jacobian H = dh/dx and noise covariance R.
// The Joseph product is evaluated as (I - K H) P (I - K H)^T = M - (M H^T) K^T with M = P - K (H P), the same
// expression associated differently (no N x N x N products).
template <int N, int M>
UpdateInfo<M> joseph_update(Vec<N>& x, SqMat<N>& p, const Vec<M>& innovation, const Mat<M, N>& h,
                            const SqMat<M>& r) {
    UpdateInfo<M> info;
    info.innovation = innovation;
    const Mat<M, N> hp = h.lazyProduct(p);  // H P = (P H^T)^T since P is symmetric
    SqMat<M> s = hp.lazyProduct(h.transpose()) + r;
    s = 0.5 * (s + s.transpose().eval());
    info.innovation_cov = s;
    const Eigen::LLT<SqMat<M>> llt(s);
    if (llt.info() != Eigen::Success) return info;
    const Mat<M, N> kt = llt.solve(hp);  // K^T = S^-1 H P
    info.nis = innovation.dot(llt.solve(innovation));
    x += kt.transpose() * innovation;
    const SqMat<N> m = p - kt.transpose().lazyProduct(hp);  // (I - K H) P
    const Mat<N, M> mht = m.lazyProduct(h.transpose());     // (I - K H) P H^T
    const Mat<N, M> kr = kt.transpose().lazyProduct(r);     // K R
    p = m - mht.lazyProduct(kt) + kr.lazyProduct(kt);        // (I - K H) P (I - K H)^T + K R K^T
    symmetrize<N>(p);
    info.ok = true;
    return info;
}

// Joseph-form update with a diagonal measurement covariance R = diag(r_diag).
template <int N, int M>
UpdateInfo<M> joseph_update_diag(Vec<N>& x, SqMat<N>& p, const Vec<M>& innovation, const Mat<M, N>& h,
                                 const Vec<M>& r_diag) {
    const SqMat<M> r = r_diag.asDiagonal();
    return joseph_update<N, M>(x, p, innovation, h, r);
}

// Normalised estimation error squared e^T P^-1 e (for consistency tests); returns -1 if P is not positive definite.
template <int N>
double nees(const Vec<N>& error, const SqMat<N>& p) {
    const Eigen::LLT<SqMat<N>> llt(p);
    if (llt.info() != Eigen::Success) return -1.0;
    return error.dot(llt.solve(error));
}

}  // namespace gdnav::core::filters
namespace gdnav { namespace filters = core::filters; }  // the short name (docs/architecture.md, "Namespaces")
