#include "random/stream.hpp"

#include <cmath>

namespace gdnav::core::rnd {

std::uint64_t fnv1a64(std::string_view text) {
    std::uint64_t h = 0xcbf29ce484222325ULL;
    for (const char c : text) {
        h ^= static_cast<std::uint8_t>(c);
        h *= 0x100000001b3ULL;
    }
    return h;
}

std::uint64_t splitmix64(std::uint64_t& state) {
    std::uint64_t z = (state += 0x9e3779b97f4a7c15ULL);
    z = (z ^ (z >> 30)) * 0xbf58476d1ce4e5b9ULL;
    z = (z ^ (z >> 27)) * 0x94d049bb133111ebULL;
    return z ^ (z >> 31);
}

Stream::Stream(std::uint64_t seed) : identity_(seed) {
    std::uint64_t st = seed;
    for (auto& w : s_) w = splitmix64(st);
}

Stream Stream::derive(std::uint64_t master_seed, std::uint64_t run_index, std::string_view name) {
    std::uint64_t st = master_seed;
    std::uint64_t a = splitmix64(st);
    st = a ^ run_index;
    std::uint64_t b = splitmix64(st);
    st = b ^ fnv1a64(name);
    return Stream(splitmix64(st));
}

Stream Stream::child(std::string_view name) const {
    std::uint64_t st = identity_ ^ fnv1a64(name);
    return Stream(splitmix64(st));
}

static inline std::uint64_t rotl(std::uint64_t x, int k) { return (x << k) | (x >> (64 - k)); }

std::uint64_t Stream::next_u64() {
    const std::uint64_t result = rotl(s_[1] * 5, 7) * 9;
    const std::uint64_t t = s_[1] << 17;
    s_[2] ^= s_[0];
    s_[3] ^= s_[1];
    s_[1] ^= s_[2];
    s_[0] ^= s_[3];
    s_[2] ^= t;
    s_[3] = rotl(s_[3], 45);
    return result;
}

double Stream::uniform() { return static_cast<double>(next_u64() >> 11) * 0x1.0p-53; }

double Stream::uniform(double lo, double hi) { return lo + (hi - lo) * uniform(); }

int Stream::uniform_int(int lo, int hi) {
    const std::uint64_t range = static_cast<std::uint64_t>(static_cast<std::int64_t>(hi) - lo) + 1u;
    const std::uint64_t limit = UINT64_MAX - (UINT64_MAX % range);
    std::uint64_t x = next_u64();
    while (x >= limit) x = next_u64();
    return static_cast<int>(static_cast<std::int64_t>(lo) + static_cast<std::int64_t>(x % range));
}

double Stream::normal() {
    if (has_spare_) {
        has_spare_ = false;
        return spare_;
    }
    double u = 0.0, v = 0.0, s = 0.0;
    do {
        u = 2.0 * uniform() - 1.0;
        v = 2.0 * uniform() - 1.0;
        s = u * u + v * v;
    } while (s >= 1.0 || s == 0.0);
    const double m = std::sqrt(-2.0 * std::log(s) / s);
    spare_ = v * m;
    has_spare_ = true;
    return u * m;
}

double Stream::normal(double mean, double sigma) { return mean + sigma * normal(); }

Eigen::Vector3d Stream::normal3() {
    const double a = normal();
    const double b = normal();
    const double c = normal();
    return {a, b, c};
}

}  // namespace gdnav::core::rnd
