#pragma once
// Aerodynamic coefficient model of the Mugin (reference "aero0" values, reduced to the data the reference states).
// Body-axis coefficients; forces F^b = qbar S (C_X, C_Y, C_Z), moments about the full-tank CG
// M^b = qbar S (b C_l, c C_m, b C_n), qbar = rho V^2 / 2.
// Non-dimensional rates from the body rate relative to NED, w_nb^b = (p, q, r):
//   p^ = p b / (2V), q^ = q c / (2V), r^ = r b / (2V).
// Longitudinal (tables in alpha, C1 biparabolic interpolation over the reference's alpha points):
//   C_X = C_X0(a) + C_X,extra + C_Xq(a) q^ + C_X,dE2 dE^2 + C_X,b2 b^2
//   C_Z = C_Z0(a) + C_Zq(a) q^ + C_Z,dE dE + C_Z,b2 b^2
//   C_m = C_m0(a) + C_mq(a) q^ + C_m,dE dE + C_m,b2 b^2
// Lateral (constant derivatives tabulated at alpha_ref = 5 deg, with the reference's linear alpha correction):
//   C_Y = C_Yb b + C_Yp p^ + C_Yr r^ + C_Yqb b q^ + C_YdA dA + C_YdR dR + C_Yab b (a - alpha_ref)
//   C_l, C_n: same form.
// Angles a (AOA), b (AOS), dE, dA, dR in rad here; the file gives per-degree surface derivatives.
// The V-tail's mixed increments (elevator on the lateral set, rudder on the longitudinal set) cancel exactly in the
// reference data for pure inputs and are therefore not modelled.
#include "config/config.hpp"
#include "flight_physics/model/table1d.hpp"
#include "math/rotation.hpp"

namespace gdnav::physics {

struct AeroCoefficients {
    double cx{0.0}, cy{0.0}, cz{0.0};  // force
    double cl{0.0}, cm{0.0}, cn{0.0};  // moment (roll, pitch, yaw)
};

struct AeroDerivatives {
    // longitudinal
    double cx_extra{0.0};
    double cx_de2_prad2{0.0};
    double cz_de_prad{0.0};
    double cm_de_prad{0.0};
    double cx_beta2_prad2{0.0};
    double cz_beta2_prad2{0.0};
    double cm_beta2_prad2{0.0};
    // lateral
    double alpha_ref_rad{0.0};
    double cy_beta{0.0}, cl_beta{0.0}, cn_beta{0.0};
    double cy_p{0.0}, cl_p{0.0}, cn_p{0.0};
    double cy_r{0.0}, cl_r{0.0}, cn_r{0.0};
    double cy_q_beta{0.0}, cl_q_beta{0.0}, cn_q_beta{0.0};
    double cy_da_prad{0.0}, cl_da_prad{0.0}, cn_da_prad{0.0};
    double cy_dr_prad{0.0}, cl_dr_prad{0.0}, cn_dr_prad{0.0};
    double cy_alpha_beta{0.0}, cl_alpha_beta{0.0}, cn_alpha_beta{0.0};
};

class Aerodynamics {
public:
    Aerodynamics() = default;
    // Reads the `aerodynamics` section of an aircraft file (keys documented in config/aircraft/mugin.yaml).
    static Aerodynamics from_config(const config::Config& cfg);

    [[nodiscard]] AeroCoefficients coefficients(double aoa_rad, double aos_rad, double p_hat, double q_hat,
                                                double r_hat, double elevator_rad, double aileron_rad,
                                                double rudder_rad) const;

    Table1D cx0, cz0, cm0;  // functions of alpha [rad], all six on the same knots
    Table1D cx_q, cz_q, cm_q;
    AeroDerivatives d;
};

}  // namespace gdnav::physics
