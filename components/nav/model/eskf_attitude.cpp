#include "eskf_attitude.hpp"

#include "filters/quat_jacobians.hpp"
#include "math/rotation.hpp"

namespace gdnav::nav::eskf {

using Mat3 = Eigen::Matrix3d;
using math::skew;

filters::SqMat<kJ> transition_leading(const att::StateVec& x, double dt_s) {
    filters::SqMat<kJ> phi = filters::SqMat<kJ>::Identity();
    phi.block<3, 3>(kTh, kW) = dt_s * filters::rot_quadratic(x.segment<4>(att::kQ));
    return phi;
}

ErrVec process_noise(const att::StateVec& q) {
    ErrVec e;
    e.segment<3>(kTh) = 4.0 * q.segment<3>(att::kQ);  // per-component quaternion variance -> angle variance
    e.segment<3>(kW) = q.segment<3>(att::kW);
    e.segment<3>(kEgyr) = q.segment<3>(att::kEgyr);
    e.segment<3>(kEmag) = q.segment<3>(att::kEmag);
    e.segment<3>(kBdev) = q.segment<3>(att::kBdev);
    return e;
}

ErrJac observation_jacobian(const att::StateVec& x, const att::PnVector& pn, att::SpecificForceModel model) {
    const Mat3 rt = filters::rot_quadratic(x.segment<4>(att::kQ)).transpose();
    const Vec3 w = x.segment<3>(att::kW);
    ErrJac h = ErrJac::Zero();
    h.block<3, 3>(att::kYgyr, kTh) = rt * skew(pn.w_ie_n + pn.w_en_n);
    h.block<3, 3>(att::kYgyr, kW).setIdentity();
    h.block<3, 3>(att::kYgyr, kEgyr).setIdentity();
    const Vec3 s = pn.w_en_n.cross(pn.v_n) - pn.g_model_n + pn.a_cor_n;
    h.block<3, 3>(att::kYacc, kTh) = rt * skew(s);
    if (const auto u = att::coupling_velocity_n(model, pn)) {
        h.block<3, 3>(att::kYacc, kTh) += skew(w) * rt * skew(*u);
        h.block<3, 3>(att::kYacc, kW) = -skew(rt * *u);
    }
    h.block<3, 3>(att::kYmag, kTh) = rt * skew(pn.b_model_n - x.segment<3>(att::kBdev));
    h.block<3, 3>(att::kYmag, kEmag).setIdentity();
    h.block<3, 3>(att::kYmag, kBdev) = -rt;
    return h;
}

void inject(att::StateVec& x, ErrCov& p, const ErrVec& dx) {
    const Vec3 dth = dx.segment<3>(kTh);
    const math::Quat q = (math::quat_from_rotv(dth) * math::from_wxyz(x.segment<4>(att::kQ))).normalized();
    x.segment<4>(att::kQ) = math::to_wxyz(q);
    x.segment<3>(att::kW) += dx.segment<3>(kW);
    x.segment<3>(att::kEgyr) += dx.segment<3>(kEgyr);
    x.segment<3>(att::kEmag) += dx.segment<3>(kEmag);
    x.segment<3>(att::kBdev) += dx.segment<3>(kBdev);
    // Reset: the error after the injection is dtheta' = dtheta - dth + 0.5 dth x dtheta (to first order), so
    // P <- G P G^T with G_theta = I + 0.5 [dth x]; only the attitude rows and columns change.
    const Mat3 g = Mat3::Identity() + 0.5 * skew(dth);
    const filters::Mat<3, kN> rows = g * p.topRows<3>();
    p.topRows<3>() = rows;
    const filters::Mat<kN, 3> cols = p.leftCols<3>() * g.transpose();
    p.leftCols<3>() = cols;
    filters::symmetrize<kN>(p);
}

ErrCov from_additive(const att::StateVec& x, const att::StateCov& pa) {
    filters::Mat<kN, att::kN> t = filters::Mat<kN, att::kN>::Zero();
    t.block<3, 4>(kTh, att::kQ) = filters::att_error_jacobian(x.segment<4>(att::kQ));
    t.block<12, 12>(kW, att::kW).setIdentity();
    ErrCov p = t * pa * t.transpose();
    filters::symmetrize<kN>(p);
    return p;
}

}  // namespace gdnav::nav::eskf
