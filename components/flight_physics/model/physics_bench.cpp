#include "flight_physics/model/physics_bench.hpp"

#include <chrono>

#include "flight_physics/model/flight_physics.hpp"

namespace gdnav::physics {

PhysicsBenchResult bench_physics_tick(const std::filesystem::path& aircraft_file,
                                      const std::filesystem::path& magnetic_file, long ticks) {
    const AircraftModel ac = AircraftModel::load(aircraft_file);
    EnvironmentParams env;
    env.magnetic = earth::MagneticModel::load(magnetic_file);
    env.wind.speed_ini_mps = env.wind.speed_end_mps = 5.0;
    env.wind.bearing_ini_rad = env.wind.bearing_end_rad = math::deg2rad(30.0);
    FlightPhysics fp(ac, env, rnd::Stream::derive(1, 0, "flight_physics/turbulence"));
    fp.initialize_trimmed(math::deg2rad(45.0), math::deg2rad(-90.0), 2700.0, 29.0, 0.0, 19.5, 0.0);
    const Controls trim = fp.trim().controls;

    const auto t0 = std::chrono::steady_clock::now();
    for (long k = 0; k < ticks; ++k) {
        Controls u = trim;
        u.elevator_rad += ((k / 2) % 2 == 0 ? 1e-4 : -1e-4);
        fp.advance(u);
    }
    const auto t1 = std::chrono::steady_clock::now();
    PhysicsBenchResult r;
    r.ticks = ticks;
    r.wall_s = std::chrono::duration<double>(t1 - t0).count();
    r.us_per_tick = 1e6 * r.wall_s / static_cast<double>(ticks);
    r.final_h_m = fp.state().h_m;
    return r;
}

}  // namespace gdnav::physics
