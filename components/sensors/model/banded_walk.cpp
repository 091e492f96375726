#include "sensors/model/banded_walk.hpp"

#include <algorithm>
#include <cmath>

namespace gdnav::sensors {

double BandedRandomWalk::step(double nu) {
    const double l = limit_;
    const double s = kBandMargin;
    double pull = 0.0;
    if (l - y_ < s) {
        pull = -0.1 * std::abs(l - s - y_) / s;
    } else if (y_ + l < s) {
        pull = 0.1 * std::abs(-l + s - y_) / s;
    }
    double y = y_ + nu + pull;
    if (hard_) {
        if (y > l) y = 2.0 * l - y;
        if (y < -l) y = -2.0 * l - y;
        y = std::clamp(y, -l, l);
    }
    y_ = y;
    return y_;
}

}  // namespace gdnav::sensors
