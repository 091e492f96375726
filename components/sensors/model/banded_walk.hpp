#pragma once
// Band-limited random walk, in units of its own step sigma (docs/sensors.md, "Band-limited random walk"; the
// reference's "grow_random_walk"). Per step, with nu ~ N(0, 1), limit L and pull zone S = kBandMargin:
//     L - y < S:   y <- y + nu - 0.1 |L - S - y| / S      (pulled down, from 0 at L - S growing linearly)
//     y + L < S:   y <- y + nu + 0.1 |-L + S - y| / S     (pulled up)
//     otherwise:   y <- y + nu
// The reference stops there (a soft band the walk may leave by a few tens of steps). The paper states the walk
// is "constrained to a band of +-L steps"; with `hard = true` a step that would leave [-L, L] is reflected at the
// limit (and clamped if a huge draw would still leave it), so the walk never leaves the band. The inertial bias
// drift uses the hard band (paper); the GNSS ionospheric walk, whose initial state may lie outside the band, uses
// the soft one (reference).
namespace gdnav::sensors {

constexpr double kBandMargin = 20.0;  // S, width of the pull zone [steps]

class BandedRandomWalk {
public:
    BandedRandomWalk() = default;
    BandedRandomWalk(double limit_steps, bool hard, double initial_steps = 0.0)
        : limit_(limit_steps), hard_(hard), y_(initial_steps) {}

    // Advances the walk by one step with the standard normal draw `nu`; returns the new value [steps].
    double step(double nu);
    [[nodiscard]] double value() const { return y_; }
    [[nodiscard]] double limit() const { return limit_; }

private:
    double limit_{100.0};
    bool hard_{true};
    double y_{0.0};
};

}  // namespace gdnav::sensors
