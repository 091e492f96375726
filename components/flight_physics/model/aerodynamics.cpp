#include "flight_physics/model/aerodynamics.hpp"

namespace gdnav::physics {

namespace {
constexpr double kPerDeg = 180.0 / math::kPi;  // per-degree derivative -> per-radian
}

Aerodynamics Aerodynamics::from_config(const config::Config& c) {
    using config::Range;
    Aerodynamics a;
    const Range any{-1e3, 1e3};
    const std::vector<double> alpha_deg = c.get_doubles("alpha_deg", 2, 64, Range{-30.0, 30.0});
    for (std::size_t i = 1; i < alpha_deg.size(); ++i)
        if (!(alpha_deg[i] > alpha_deg[i - 1])) c.fail("alpha_deg", "must be strictly increasing");
    std::vector<double> alpha_rad;
    for (double v : alpha_deg) alpha_rad.push_back(math::deg2rad(v));
    auto table = [&](const char* key) {
        const auto y = c.get_doubles(key, alpha_deg.size(), alpha_deg.size(), any);
        return Table1D(alpha_rad, y);
    };
    a.cx0 = table("cx0");
    a.cz0 = table("cz0");
    a.cm0 = table("cm0");
    a.cx_q = table("cx_q");
    a.cz_q = table("cz_q");
    a.cm_q = table("cm_q");

    AeroDerivatives& d = a.d;
    d.cx_extra = c.get_double("cx_extra", any);
    d.cx_de2_prad2 = c.get_double("cx_de2_per_deg2", any) * kPerDeg * kPerDeg;
    d.cz_de_prad = c.get_double("cz_de_per_deg", any) * kPerDeg;
    d.cm_de_prad = c.get_double("cm_de_per_deg", any) * kPerDeg;
    d.cx_beta2_prad2 = c.get_double("cx_beta2_per_rad2", any);
    d.cz_beta2_prad2 = c.get_double("cz_beta2_per_rad2", any);
    d.cm_beta2_prad2 = c.get_double("cm_beta2_per_rad2", any);

    const config::Config lat = c.child("lateral");
    d.alpha_ref_rad = lat.get_angle_deg("alpha_ref_deg", Range{-30.0, 30.0});
    auto triple = [&](const char* key, double& y, double& l, double& n, double scale) {
        const Eigen::Vector3d v = lat.get_vec3(key, any);
        y = v.x() * scale;
        l = v.y() * scale;
        n = v.z() * scale;
    };
    triple("beta_per_rad", d.cy_beta, d.cl_beta, d.cn_beta, 1.0);
    triple("p_hat", d.cy_p, d.cl_p, d.cn_p, 1.0);
    triple("r_hat", d.cy_r, d.cl_r, d.cn_r, 1.0);
    triple("q_hat_beta_per_rad", d.cy_q_beta, d.cl_q_beta, d.cn_q_beta, 1.0);
    triple("aileron_per_deg", d.cy_da_prad, d.cl_da_prad, d.cn_da_prad, kPerDeg);
    triple("rudder_per_deg", d.cy_dr_prad, d.cl_dr_prad, d.cn_dr_prad, kPerDeg);
    triple("alpha_beta_per_rad2", d.cy_alpha_beta, d.cl_alpha_beta, d.cn_alpha_beta, 1.0);
    return a;
}

AeroCoefficients Aerodynamics::coefficients(double a, double b, double p_hat, double q_hat, double r_hat, double de,
                                            double da, double dr) const {
    AeroCoefficients k;
    const double b2 = b * b;
    const Table1D::Stencil st = cx0.stencil(a);  // the six alpha tables share their knots
    k.cx = cx0.apply(st) + d.cx_extra + cx_q.apply(st) * q_hat + d.cx_de2_prad2 * de * de + d.cx_beta2_prad2 * b2;
    k.cz = cz0.apply(st) + cz_q.apply(st) * q_hat + d.cz_de_prad * de + d.cz_beta2_prad2 * b2;
    k.cm = cm0.apply(st) + cm_q.apply(st) * q_hat + d.cm_de_prad * de + d.cm_beta2_prad2 * b2;
    const double ab = b * (a - d.alpha_ref_rad);
    const double qb = q_hat * b;
    k.cy = d.cy_beta * b + d.cy_p * p_hat + d.cy_r * r_hat + d.cy_q_beta * qb + d.cy_da_prad * da + d.cy_dr_prad * dr +
           d.cy_alpha_beta * ab;
    k.cl = d.cl_beta * b + d.cl_p * p_hat + d.cl_r * r_hat + d.cl_q_beta * qb + d.cl_da_prad * da + d.cl_dr_prad * dr +
           d.cl_alpha_beta * ab;
    k.cn = d.cn_beta * b + d.cn_p * p_hat + d.cn_r * r_hat + d.cn_q_beta * qb + d.cn_da_prad * da + d.cn_dr_prad * dr +
           d.cn_alpha_beta * ab;
    return k;
}

}  // namespace gdnav::physics
