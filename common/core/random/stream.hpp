#pragma once
// Seeded random streams whose output is defined by gdnav's own code (not by the standard library's
// distributions, which differ between library versions).
//   generator: xoshiro256** (Blackman & Vigna), state filled by splitmix64;
//   seeding:   splitmix64 over (master seed, run index, FNV-1a 64 of the stream name);
//   uniform:   53-bit mantissa in [0, 1);
//   normal:    Marsaglia polar method (sqrt and log only; both deterministic on IEEE-754 with glibc).
// Every model owns its stream: Stream::derive(seed, run, "sensors_inertial/gyr"). Adding a model never changes
// another model's draws.
#include <array>
#include <cstdint>
#include <string_view>

#include <Eigen/Core>

namespace gdnav::core::rnd {

std::uint64_t fnv1a64(std::string_view text);
std::uint64_t splitmix64(std::uint64_t& state);

class Stream {
public:
    Stream() : Stream(0u) {}
    explicit Stream(std::uint64_t seed);
    // The stream of model `name` in run `run_index` of a batch with master seed `master_seed`.
    static Stream derive(std::uint64_t master_seed, std::uint64_t run_index, std::string_view name);
    // A sub-stream for a part of this stream's owner (independent of how many draws this stream made).
    [[nodiscard]] Stream child(std::string_view name) const;

    std::uint64_t next_u64();
    double uniform();                          // [0, 1)
    double uniform(double lo, double hi);      // [lo, hi)
    int uniform_int(int lo, int hi);           // inclusive, unbiased
    double normal();                           // N(0, 1)
    double normal(double mean, double sigma);  // N(mean, sigma^2)
    Eigen::Vector3d normal3();                 // three independent N(0, 1)

    [[nodiscard]] std::uint64_t identity() const { return identity_; }

private:
    std::array<std::uint64_t, 4> s_{};
    std::uint64_t identity_{0};
    bool has_spare_{false};
    double spare_{0.0};
};

}  // namespace gdnav::core::rnd
namespace gdnav { namespace rnd = core::rnd; }  // the short name (docs/architecture.md, "Namespaces")
