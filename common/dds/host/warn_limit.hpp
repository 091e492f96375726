#pragma once
// A warning that can come once per sample (a foreign writer, a bad stamp, a sample too far ahead) must not flood the
// log: its first occurrence is logged, later ones are counted and logged as one line with their number at most once
// per period of wall time. Every occurrence is counted, so the run's summary can give the total.
#include <cstdint>

#include "dds/compat.hpp"

namespace gdnav::dds::host {

class WarnLimit {
public:
    static constexpr double kPeriodS = 5.0;

    // One occurrence at wall time now_s: the number of occurrences the line to log now stands for (this one and the
    // unlogged ones before it), or 0 when nothing is to be logged now.
    std::uint64_t occur(double now_s) {
        ++total_;
        ++unlogged_;
        if (logged_ && now_s < next_s_) return 0;
        logged_ = true;
        next_s_ = now_s + kPeriodS;
        const std::uint64_t n = unlogged_;
        unlogged_ = 0;
        return n;
    }
    [[nodiscard]] std::uint64_t total() const { return total_; }

private:
    bool logged_{false};
    double next_s_{0.0};
    std::uint64_t total_{0};
    std::uint64_t unlogged_{0};
};

}  // namespace gdnav::dds::host
