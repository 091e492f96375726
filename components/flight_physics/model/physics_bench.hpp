#pragma once
// Cost of one 10-ms physics tick (FlightPhysics::advance with 5 Heun sub-steps), for `gdnav bench`.
// Runs the Mugin trimmed at 29 m/s, Hp 2700 m, with Dryden turbulence (factor 0.5, default intensity), a 5 m/s wind and
// controls that change every second tick (as a 50-Hz controller would), and measures wall time (steady_clock).
#include <filesystem>

namespace gdnav::physics {

struct PhysicsBenchResult {
    long ticks{0};
    double wall_s{0.0};
    double us_per_tick{0.0};
    double final_h_m{0.0};  // keeps the work observable
};

PhysicsBenchResult bench_physics_tick(const std::filesystem::path& aircraft_file,
                                      const std::filesystem::path& magnetic_file, long ticks = 20000);

}  // namespace gdnav::physics
