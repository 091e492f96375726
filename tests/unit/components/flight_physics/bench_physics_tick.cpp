// Google Benchmark of one 10-ms physics tick (FlightPhysics::advance: 5 Heun sub-steps at 500 Hz).
#include <benchmark/benchmark.h>

#include "flight_physics/model/flight_physics.hpp"
#include "flight_physics/model/physics_bench.hpp"

namespace {
const std::string kRoot = GDNAV_SOURCE_DIR;

void BM_PhysicsTick(benchmark::State& state) {
    using namespace gdnav;
    const auto ac = physics::AircraftModel::load(kRoot + "/config/aircraft/mugin.yaml");
    physics::EnvironmentParams env;
    env.magnetic = earth::MagneticModel::load(kRoot + "/config/earth/magnetic_wisconsin.yaml");
    env.wind.speed_ini_mps = env.wind.speed_end_mps = 5.0;
    physics::FlightPhysics fp(ac, env, rnd::Stream::derive(1, 0, "flight_physics/turbulence"));
    fp.initialize_trimmed(math::deg2rad(45.0), math::deg2rad(-90.0), 2700.0, 29.0, 0.0, 19.5, 0.0);
    physics::Controls u = fp.trim().controls;
    long k = 0;
    for (auto _ : state) {
        u.elevator_rad += ((k++ / 2) % 2 == 0 ? 1e-5 : -1e-5);
        fp.advance(u);
        benchmark::DoNotOptimize(fp.truth().h_m);
    }
}
BENCHMARK(BM_PhysicsTick);

// The plain function `gdnav bench` can call.
void BM_PlainFunction(benchmark::State& state) {
    for (auto _ : state) {
        const auto r = gdnav::physics::bench_physics_tick(kRoot + "/config/aircraft/mugin.yaml",
                                                          kRoot + "/config/earth/magnetic_wisconsin.yaml", 20000);
        state.counters["us_per_tick"] = r.us_per_tick;
    }
}
BENCHMARK(BM_PlainFunction)->Iterations(1)->Unit(benchmark::kMillisecond);
}  // namespace

BENCHMARK_MAIN();
