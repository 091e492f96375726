#pragma once
// The rejected-sample reporting shared by the nav components: each counts the samples its filter rejects and those
// it refused before initialising, and reports the counts on ComponentStatus (MODE) at the first rejection, then at
// most once per kPeriod_s of simulated time while the count grows, and once more on the last step of the run; and
// in the log at the end of the run.
#include <cstdint>
#include <limits>
#include <string>

#include "framework/component.hpp"

namespace gdnav::nav {

class RejectionReporting : public framework::Component {
public:
    static constexpr double kPeriod_s = 10.0;
    using Component::Component;
    // Logs the counts at the end of a run that rejected anything.
    void finish(bool) override;

protected:
    // Every rejected sample so far, of every kind.
    [[nodiscard]] virtual std::uint64_t total() const = 0;
    // The counts by kind, as they follow "rejected samples: " in the report.
    [[nodiscard]] virtual std::string count_details() const = 0;

    // The report; `summary` marks the one of the end of the run.
    [[nodiscard]] std::string counts(bool summary) const;
    // Publishes the counts when a report is due at this step.
    void report_counts(const framework::StepContext& ctx);
    void reject_before_init() { ++init_rejected_; }
    [[nodiscard]] std::uint64_t rejected_before_init() const { return init_rejected_; }

private:
    std::uint64_t init_rejected_{0};
    std::uint64_t reported_{0};
    double t_reported_s_{-std::numeric_limits<double>::infinity()};
};

}  // namespace gdnav::nav
