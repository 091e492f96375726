#include "flight_physics/model/propulsion.hpp"

#include <algorithm>
#include <cmath>

#include "atmosphere/insa.hpp"
#include "math/rotation.hpp"

namespace gdnav::physics {

Propulsion Propulsion::from_config(const config::Config& c) {
    using config::Range;
    Propulsion p;
    p.max_power_W = c.get_double("max_power_W", Range{1.0, 1e6});
    p.diameter_m = c.get_double("propeller_diameter_m", Range{0.01, 10.0});
    p.fuel_kgpWs = c.get_double("fuel_consumption_kg_per_W_s", Range{0.0, 1e-3});
    const auto lim = c.get_doubles("speed_limits_rps", 2, 2, Range{1.0, 1000.0});
    if (!(lim[1] > lim[0])) c.fail("speed_limits_rps", "must be [min, max] with max > min");
    p.speed_min_rps = lim[0];
    p.speed_max_rps = lim[1];
    const auto j = c.get_doubles("advance_ratio", 2, 1000, Range{0.0, 10.0});
    for (std::size_t i = 1; i < j.size(); ++i)
        if (!(j[i] > j[i - 1])) c.fail("advance_ratio", "must be strictly increasing");
    p.ct = Table1D(j, c.get_doubles("thrust_coefficient", j.size(), j.size(), Range{-1.0, 1.0}));
    // Cp > 0: the absorbed power rho n^3 D^5 Cp must grow with the engine speed n (solve_speed_rps); C_T may be < 0.
    p.cp = Table1D(j, c.get_doubles("power_coefficient", j.size(), j.size(), Range{1.0e-6, 1.0}));
    return p;
}

double Propulsion::power_W(double throttle, double p_Pa, double T_K) const {
    const double cap = max_power_W * (p_Pa / atm::kP0_Pa) / std::sqrt(T_K / atm::kT0_K);
    return std::min(max_power_W * throttle, cap);
}

double Propulsion::solve_speed_rps(double power, double tas, double rho, double n_guess) const {
    // f(n) = Cp(V / (n D)) rho n^3 D^5 - P is increasing in n; f'(n) = rho D^5 n^2 (3 Cp - J Cp').
    const double d5 = diameter_m * diameter_m * diameter_m * diameter_m * diameter_m;
    auto f = [&](double n, double& df) {
        const double j = tas / (n * diameter_m);
        const auto [c, dc] = cp.eval(j);
        df = rho * d5 * n * n * (3.0 * c - j * dc);
        return c * rho * n * n * n * d5 - power;
    };
    const double lo0 = speed_min_rps, hi0 = speed_max_rps;
    double df = 0.0;
    // Fast path: plain Newton from a warm start inside the bounds. Converged when a step is below 1e-7 n: the
    // remaining error is then of order (step / n)^2 n.
    if (n_guess > lo0 && n_guess < hi0) {
        double n = n_guess;
        for (int i = 0; i < 4; ++i) {
            const double fn = f(n, df);
            if (!(df > 0.0)) break;
            const double next = n - fn / df;
            if (!(next > lo0 && next < hi0)) break;
            const double step = next - n;
            n = next;
            if (std::abs(step) < 1e-7 * n) return n;
        }
    }
    // Safeguarded Newton on the bracket [n_min, n_max]; the bounds are returned when the solution lies outside.
    double lo = lo0, hi = hi0;
    if (f(lo, df) >= 0.0) return lo;
    if (f(hi, df) <= 0.0) return hi;
    double n = 0.5 * (lo + hi);
    for (int i = 0; i < 100; ++i) {
        const double fn = f(n, df);
        if (fn > 0.0) {
            hi = n;
        } else {
            lo = n;
        }
        double next = (df > 0.0) ? n - fn / df : 0.5 * (lo + hi);
        if (!(next > lo && next < hi)) next = 0.5 * (lo + hi);
        const double step = next - n;
        n = next;
        if (std::abs(step) < 1e-12 * n || hi - lo < 1e-12 * n) break;
    }
    return n;
}

PropulsionOutput Propulsion::compute(double throttle, double tas, double rho, double p_Pa, double T_K,
                                     double n_guess) const {
    PropulsionOutput o;
    o.power_W = power_W(throttle, p_Pa, T_K);
    o.speed_rps = solve_speed_rps(o.power_W, tas, rho, n_guess);
    o.advance_ratio = tas / (o.speed_rps * diameter_m);
    const double d2 = diameter_m * diameter_m;
    o.thrust_N = ct(o.advance_ratio) * rho * o.speed_rps * o.speed_rps * d2 * d2;
    o.torque_x_Nm = -o.power_W / (2.0 * math::kPi * o.speed_rps);
    o.mass_rate_kgps = -fuel_kgpWs * o.power_W;
    return o;
}

}  // namespace gdnav::physics
