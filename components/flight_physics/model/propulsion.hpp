#pragma once
// Piston engine + fixed-pitch propeller (quasi-static engine speed, no rpm dynamics).
//   Engine power   P = min(P_max dT, P_max delta / sqrt(theta)),  delta = p / p0, theta = T / T0
//                  (throttle dT in [0, 1] scales the sea-level maximum; altitude only caps it)
//   Engine speed   n [rev/s] solves Cp(J) rho n^3 D^5 = P with J = V / (n D), within [n_min, n_max]
//                  (safeguarded Newton iterated to convergence, warm-started from the previous n)
//   Thrust         T = Ct(J) rho n^2 D^4 along +x_b, through the CG (no moment)
//   Torque         M_prop^b = (-P / (2 pi n), 0, 0)
//   Fuel flow      m_dot = -c_f P
// Ct(J) and Cp(J) are tables (C1 biparabolic interpolation over the file's points).
#include "config/config.hpp"
#include "flight_physics/model/table1d.hpp"

namespace gdnav::physics {

struct PropulsionOutput {
    double power_W{0.0};
    double speed_rps{0.0};  // propeller revolutions per second
    double advance_ratio{0.0};
    double thrust_N{0.0};
    double torque_x_Nm{0.0};     // reaction torque about x_b
    double mass_rate_kgps{0.0};  // negative: fuel burnt
};

class Propulsion {
public:
    Propulsion() = default;
    // Reads the `propulsion` section of an aircraft file.
    static Propulsion from_config(const config::Config& cfg);

    [[nodiscard]] double power_W(double throttle, double p_Pa, double T_K) const;
    // n_guess_rps <= 0: cold start.
    [[nodiscard]] PropulsionOutput compute(double throttle, double tas_mps, double rho_kgpm3, double p_Pa, double T_K,
                                           double n_guess_rps = 0.0) const;
    [[nodiscard]] double solve_speed_rps(double power_W, double tas_mps, double rho_kgpm3, double n_guess_rps) const;

    double max_power_W{0.0};
    double diameter_m{0.0};
    double fuel_kgpWs{0.0};
    double speed_min_rps{0.0};
    double speed_max_rps{0.0};
    Table1D ct, cp;  // functions of J
};

}  // namespace gdnav::physics
