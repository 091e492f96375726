#include "gnss_aided_model.hpp"

#include <cmath>

#include "math/rotation.hpp"
#include "nav_earth.hpp"

namespace gdnav::nav::aided {

using Mat3 = Eigen::Matrix3d;

StateVec derivative(const StateVec& x, const Quat& q_nb) {
    const double lat = x(kLat), h = x(kH);
    const Vec3 v = x.segment<3>(kV);
    StateVec d = StateVec::Zero();
    d.segment<3>(kLon) = earth::geodetic_rates(lat, h, v);
    const Vec3 a = earth::w_en_n(lat, h, v) + 2.0 * earth::w_ie_n(lat);
    d.segment<3>(kV) = q_nb.normalized().toRotationMatrix() * x.segment<3>(kF) + earth::gravity_n(lat, h) - a.cross(v);
    return d;
}

StateCov state_jacobian(const StateVec& x, const Quat& q_nb) {
    const double lat = x(kLat), h = x(kH);
    const Vec3 v = x.segment<3>(kV);
    const double vn = v.x(), ve = v.y();
    const earth::Radii r = earth::radii(lat);
    const double s = std::sin(lat), c = std::cos(lat), t = std::tan(lat);
    const double nh = r.n_m + h, mh = r.m_m + h;
    StateCov a = StateCov::Zero();
    // geodetic rates
    a(kLon, kLat) = -ve * (r.dn_dlat * c - nh * s) / (nh * nh * c * c);
    a(kLon, kH) = -ve / (nh * nh * c);
    a(kLon, kV + 1) = 1.0 / (nh * c);
    a(kLat, kLat) = -vn * r.dm_dlat / (mh * mh);
    a(kLat, kH) = -vn / (mh * mh);
    a(kLat, kV) = 1.0 / mh;
    a(kH, kV + 2) = -1.0;
    // velocity: v_dot = R f + g e3 - (w_en + 2 w_ie) x v
    const Vec3 w = earth::w_en_n(lat, h, v) + 2.0 * earth::w_ie_n(lat);
    Mat3 dwen_dv = Mat3::Zero();
    dwen_dv(0, 1) = 1.0 / nh;
    dwen_dv(1, 0) = -1.0 / mh;
    dwen_dv(2, 1) = -t / nh;
    const Vec3 dwen_dlat(-ve * r.dn_dlat / (nh * nh), vn * r.dm_dlat / (mh * mh),
                         -ve * (nh / (c * c) - t * r.dn_dlat) / (nh * nh));
    const Vec3 dwie_dlat(-earth::kWie_rps * s, 0.0, -earth::kWie_rps * c);
    const Vec3 dwen_dh(-ve / (nh * nh), vn / (mh * mh), ve * t / (nh * nh));
    const earth::Gravity g = earth::normal_gravity(lat, h);
    const Mat3 vx = math::skew(v);
    a.block<3, 3>(kV, kV) = -math::skew(w) + vx * dwen_dv;
    a.block<3, 1>(kV, kLat) = vx * (dwen_dlat + 2.0 * dwie_dlat) + Vec3(0.0, 0.0, g.dg_dlat);
    a.block<3, 1>(kV, kH) = vx * dwen_dh + Vec3(0.0, 0.0, g.dg_dh);
    a.block<3, 3>(kV, kF) = q_nb.normalized().toRotationMatrix();
    return a;
}

filters::Vec<kMfast> observe_fast(const StateVec& x) { return x.segment<3>(kF) + x.segment<3>(kE); }

filters::Mat<kMfast, kN> jacobian_fast() {
    filters::Mat<kMfast, kN> h = filters::Mat<kMfast, kN>::Zero();
    h.block<3, 3>(0, kF).setIdentity();
    h.block<3, 3>(0, kE).setIdentity();
    return h;
}

filters::Vec<kMslow> observe_slow(const StateVec& x) {
    filters::Vec<kMslow> y;
    y << observe_fast(x), x.segment<3>(kV), x(kLon), x(kLat), x(kH);
    return y;
}

filters::Mat<kMslow, kN> jacobian_slow() {
    filters::Mat<kMslow, kN> h = filters::Mat<kMslow, kN>::Zero();
    h.topRows<3>() = jacobian_fast();
    h.block<3, 3>(3, kV).setIdentity();
    h(6, kLon) = h(7, kLat) = h(8, kH) = 1.0;
    return h;
}

}  // namespace gdnav::nav::aided
