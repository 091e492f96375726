#include "nav_bench.hpp"

#include <ctime>
#include <vector>

#include "air_data_filter.hpp"
#include "attitude_filter.hpp"
#include "nav_synthetic.hpp"
#include "position_filter.hpp"

namespace gdnav::nav {

namespace {
// Process CPU time (less sensitive than wall time to other processes sharing the cores).
double cpu_us() { return 1e6 * static_cast<double>(std::clock()) / CLOCKS_PER_SEC; }
}  // namespace

NavBenchResult bench_nav_filters(const config::Config& tuning, const config::Config& variant, int steps,
                                 std::uint64_t seed) {
    const rnd::Stream root = rnd::Stream::derive(seed, 0, "nav_bench");
    AirDataFilter air;
    AttitudeFilter att;
    PositionFilter pos;
    air.configure(tuning.child("air"), root.child("air"));
    att.configure(tuning.child("attitude"), variant.child("attitude"), root.child("att"));
    pos.configure(tuning.child("position"), variant.child("position"), root.child("pos"));
    synth::Scenario sc;
    sc.dt_s = att.tuning().dt_s;
    sc.yaw_rate_rps = 0.02;  // gentle turn
    sc.bank_rad = 0.1;
    synth::Generator gen(sc, root.child("data"));
    const int n = steps < 2 ? 2 : steps;
    std::vector<synth::Sample> data;
    data.reserve(static_cast<std::size_t>(n) + 1);
    for (int i = 0; i <= n; ++i) data.push_back(gen.next());
    const Alignment align = gen.alignment(root.child("alignment"));
    const synth::Sample& s0 = data[0];
    std::vector<AirDataEstimate> as(data.size());
    std::vector<AttitudeEstimate> qs(data.size());
    std::vector<PositionEstimate> ps(data.size());
    auto init = [&]() {
        as[0] = air.initialize(0, 0.0, s0.air, s0.atm);
        qs[0] = att.initialize(0, 0.0, s0.imu, s0.mag, as[0], s0.gnss, &align);
        ps[0] = pos.initialize(0, 0.0, s0.imu, s0.gnss, as[0], qs[0], &align);
    };
    // Reference run of the whole chain (untimed): its outputs feed the per-filter timing loops below.
    init();
    for (int k = 1; k <= n; ++k) {
        const double t = k * sc.dt_s;
        as[k] = air.step(k, t, data[k].air, data[k].atm);
        qs[k] = att.step(k, t, data[k].imu, data[k].mag, ps[k - 1]);
        ps[k] = pos.step(k, t, data[k].imu, data[k].gnss, as[k], qs[k]);
    }
    NavBenchResult res;
    res.steps = n;
    init();
    double t0 = cpu_us();
    for (int k = 1; k <= n; ++k) as[k] = air.step(k, k * sc.dt_s, data[k].air, data[k].atm);
    res.air_us_per_step = (cpu_us() - t0) / n;
    t0 = cpu_us();
    for (int k = 1; k <= n; ++k) qs[k] = att.step(k, k * sc.dt_s, data[k].imu, data[k].mag, ps[k - 1]);
    res.att_us_per_step = (cpu_us() - t0) / n;
    t0 = cpu_us();
    for (int k = 1; k <= n; ++k) ps[k] = pos.step(k, k * sc.dt_s, data[k].imu, data[k].gnss, as[k], qs[k]);
    res.pos_aided_us_per_step = (cpu_us() - t0) / n;
    pos.set_gnss_publisher_dead();
    t0 = cpu_us();
    for (int k = 1; k <= n; ++k) ps[k] = pos.step(n + k, (n + k) * sc.dt_s, data[k].imu, data[k].gnss, as[k], qs[k]);
    res.pos_denied_us_per_step = (cpu_us() - t0) / n;
    return res;
}

}  // namespace gdnav::nav
