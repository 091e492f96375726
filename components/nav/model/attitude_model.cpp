#include "attitude_model.hpp"

#include "filters/quat_jacobians.hpp"
#include "math/rotation.hpp"
#include "nav_earth.hpp"

namespace gdnav::nav::att {

using filters::Quat4;
using Mat3 = Eigen::Matrix3d;

PnVector make_pn(const PositionEstimate& pos) {
    PnVector pn;
    pn.g_model_n = earth::gravity_n(pos.lat_rad, pos.h_m);
    pn.b_model_n = earth::magnetic_model_n(pos.lon_rad, pos.lat_rad);
    pn.v_n = pos.v_n_mps;
    pn.wind_n = pos.wind_n_mps;
    pn.w_ie_n = earth::w_ie_n(pos.lat_rad);
    pn.w_en_n = earth::w_en_n(pos.lat_rad, pos.h_m, pos.v_n_mps);
    pn.a_cor_n = earth::a_cor_n(pos.lat_rad, pos.v_n_mps);
    pn.acc_err_b = pos.acc_err_b_mps2;
    return pn;
}

std::optional<Vec3> coupling_velocity_n(SpecificForceModel model, const PnVector& pn) {
    switch (model) {
        case SpecificForceModel::kBaseline: return Vec3(pn.v_n - pn.wind_n);
        case SpecificForceModel::kZeroBodyDerivatives: return pn.v_n;
        case SpecificForceModel::kZeroNedDerivatives: return std::nullopt;
    }
    return std::nullopt;
}

StateVec derivative(const StateVec& x) {
    StateVec d = StateVec::Zero();
    d.segment<4>(kQ) = filters::quat_kinematics(x.segment<4>(kQ), x.segment<3>(kW));
    return d;
}

StateCov state_jacobian(const StateVec& x) {
    StateCov a = StateCov::Zero();
    a.block<4, 4>(kQ, kQ) = 0.5 * filters::omega_right(x.segment<3>(kW));
    a.block<4, 3>(kQ, kW) = 0.5 * filters::xi(x.segment<4>(kQ));
    return a;
}

namespace {
// Terms of the specific-force observation that do not depend on the variant, rotated into body by the caller.
Vec3 specific_force_ned_terms(const PnVector& pn) {
    return pn.w_en_n.cross(pn.v_n) - pn.g_model_n + pn.a_cor_n;
}
}  // namespace

MeasVec observe(const StateVec& x, const PnVector& pn, SpecificForceModel model) {
    const Quat4 q = x.segment<4>(kQ);
    const Mat3 rt = filters::rot_quadratic(q).transpose();
    const Vec3 w = x.segment<3>(kW);
    MeasVec y;
    y.segment<3>(kYgyr) = w + rt * (pn.w_ie_n + pn.w_en_n) + x.segment<3>(kEgyr);
    Vec3 f = rt * specific_force_ned_terms(pn) + pn.acc_err_b;
    if (const auto u = coupling_velocity_n(model, pn)) f += w.cross(rt * *u);
    y.segment<3>(kYacc) = f;
    y.segment<3>(kYmag) = rt * (pn.b_model_n - x.segment<3>(kBdev)) + x.segment<3>(kEmag);
    return y;
}

MeasJac observation_jacobian(const StateVec& x, const PnVector& pn, SpecificForceModel model) {
    const Quat4 q = x.segment<4>(kQ);
    const Mat3 rt = filters::rot_quadratic(q).transpose();
    const Vec3 w = x.segment<3>(kW);
    MeasJac h = MeasJac::Zero();
    // gyro
    h.block<3, 4>(kYgyr, kQ) = filters::d_rot_t_dq(q, pn.w_ie_n + pn.w_en_n);
    h.block<3, 3>(kYgyr, kW).setIdentity();
    h.block<3, 3>(kYgyr, kEgyr).setIdentity();
    // accelerometer: d/dq [R^T c] + [w x] d/dq [R^T u];  d/dw (w x u_b) = -[u_b x]
    h.block<3, 4>(kYacc, kQ) = filters::d_rot_t_dq(q, specific_force_ned_terms(pn));
    if (const auto u = coupling_velocity_n(model, pn)) {
        h.block<3, 4>(kYacc, kQ) += math::skew(w) * filters::d_rot_t_dq(q, *u);
        h.block<3, 3>(kYacc, kW) = -math::skew(rt * *u);
    }
    // magnetometer
    h.block<3, 4>(kYmag, kQ) = filters::d_rot_t_dq(q, pn.b_model_n - x.segment<3>(kBdev));
    h.block<3, 3>(kYmag, kEmag).setIdentity();
    h.block<3, 3>(kYmag, kBdev) = -rt;
    return h;
}

}  // namespace gdnav::nav::att
