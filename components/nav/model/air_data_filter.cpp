#include "air_data_filter.hpp"

#include <cmath>
#include <limits>
#include <stdexcept>

#include "math/rotation.hpp"
#include "nav_earth.hpp"
#include "tuning_ranges.hpp"

namespace gdnav::nav {

using config::Range;
using namespace tuning_ranges;

void AirDataFilter::configure(const config::Config& tuning, rnd::Stream /*stream*/) {
    Tuning t;
    t.dt_s = tuning.get_double("dt_s", Range{1e-4, 1.0});
    const config::Config q = tuning.child("q_per_step");
    t.q_diag << q.get_double("tas_m2ps2", kVariance), q.get_double("aoa_rad2", kVariance),
        q.get_double("aos_rad2", kVariance), q.get_double("T_K2", kVariance),
        q.get_double("Hp_m2", kVariance), q.get_double("roc_m2ps2", kVariance),
        q.get_double("tas_dot_m2ps4", kVariance), q.get_double("aoa_dot_rad2ps2", kVariance),
        q.get_double("aos_dot_rad2ps2", kVariance);
    const config::Config s = tuning.child("sensor_sigma");
    const config::Config b = tuning.child("sensor_bias_sigma");
    auto read = [](const config::Config& c) {
        MeasVec v;
        v << c.get_double("tas_mps", kPositiveSigma), c.get_angle_deg("aoa_deg", Range{1e-6, 10.0}),
            c.get_angle_deg("aos_deg", Range{1e-6, 10.0}), c.get_double("T_K", kPositiveSigma),
            c.get_double("p_Pa", kPositiveSigma);
        return v;
    };
    t.r_diag = read(s).array().square();
    t.bias_sigma = read(b);
    tuning.finish();
    configure(t);
}

void AirDataFilter::configure(const Tuning& tuning) {
    tun_ = tuning;
    phi_ = filters::transition_matrix<kN>(state_jacobian(), tun_.dt_s, 1);  // exact: A^2 = 0
    rej_ = {};
    initialized_ = false;
}

AirDataFilter::StateVec AirDataFilter::derivative(const StateVec& x) {
    StateVec d = StateVec::Zero();
    d(0) = x(6);
    d(1) = x(7);
    d(2) = x(8);
    d(4) = x(5);
    return d;
}

AirDataFilter::StateCov AirDataFilter::state_jacobian() {
    StateCov a = StateCov::Zero();
    a(0, 6) = a(1, 7) = a(2, 8) = a(4, 5) = 1.0;
    return a;
}

AirDataFilter::MeasVec AirDataFilter::observe(const StateVec& x) {
    MeasVec y;
    y << x(0), x(1), x(2), x(3), earth::pressure_from_Hp(x(4));
    return y;
}

AirDataFilter::MeasJac AirDataFilter::observation_jacobian(const StateVec& x) {
    MeasJac h = MeasJac::Zero();
    h(0, 0) = h(1, 1) = h(2, 2) = h(3, 3) = 1.0;
    h(4, 4) = earth::dpressure_dHp(x(4));
    return h;
}

AirDataEstimate AirDataFilter::initialize(std::uint64_t k, double t_s, const AirSample& air, const AtmSample& atm) {
    if (!checks::air_ok(air) || !checks::atm_ok(atm))
        throw std::invalid_argument("AirDataFilter::initialize: non-finite or out-of-range air data sample");
    x_.setZero();
    x_ << air.tas_mps, air.aoa_rad, air.aos_rad, atm.T_K, earth::Hp_from_pressure(atm.p_Pa), 0.0, 0.0, 0.0, 0.0;
    p_.setZero();
    for (int i = 0; i < 4; ++i) p_(i, i) = tun_.r_diag(i) + tun_.bias_sigma(i) * tun_.bias_sigma(i);
    const double sp = std::sqrt(tun_.r_diag(4) + tun_.bias_sigma(4) * tun_.bias_sigma(4));
    const double dhp = earth::Hp_from_pressure(atm.p_Pa + sp) - x_(4);
    p_(4, 4) = dhp * dhp;
    initialized_ = true;
    return output(k, t_s);
}

AirDataEstimate AirDataFilter::step(std::uint64_t k, double t_s, const AirSample& air, const AtmSample& atm) {
    if (!initialized_) throw std::logic_error("AirDataFilter::step before initialize");
    // Propagate (linear model: Phi x equals the forward-Euler x + dt f(x)).
    x_ = phi_ * x_;
    filters::propagate_covariance_diag<kN>(p_, phi_, tun_.q_diag);
    // Update with the samples that pass the input checks (rows 0-2: AirSample, rows 3-4: AtmSample).
    const bool air_good = checks::air_ok(air), atm_good = checks::atm_ok(atm);
    if (!air_good) ++rej_.air;
    if (!atm_good) ++rej_.atm;
    MeasVec y;
    y << air.tas_mps, air.aoa_rad, air.aos_rad, atm.T_K, atm.p_Pa;
    if (air_good && atm_good) {
        const MeasVec r = y - observe(x_);
        filters::joseph_update_diag<kN, kM>(x_, p_, r, observation_jacobian(x_), tun_.r_diag);
    } else if (air_good) {
        const filters::Vec<3> r = y.head<3>() - observe(x_).head<3>();
        const filters::Mat<3, kN> h = observation_jacobian(x_).topRows<3>();
        filters::joseph_update_diag<kN, 3>(x_, p_, r, h, tun_.r_diag.head<3>().eval());
    } else if (atm_good) {
        const filters::Vec<2> r = y.tail<2>() - observe(x_).tail<2>();
        const filters::Mat<2, kN> h = observation_jacobian(x_).bottomRows<2>();
        filters::joseph_update_diag<kN, 2>(x_, p_, r, h, tun_.r_diag.tail<2>().eval());
    }
    return output(k, t_s);
}

AirDataEstimate AirDataFilter::output(std::uint64_t k, double t_s) const {
    AirDataEstimate e;
    e.stamp = {k, t_s};
    e.tas_mps = x_(0);
    e.aoa_rad = x_(1);
    e.aos_rad = x_(2);
    e.T_K = x_(3);
    e.Hp_m = x_(4);
    e.dT_K = earth::dT_from(x_(3), x_(4));
    e.roc_mps = x_(5);
    e.tas_dot_mps2 = x_(6);
    e.aoa_dot_rps = x_(7);
    e.aos_dot_rps = x_(8);
    return e;
}

}  // namespace gdnav::nav
