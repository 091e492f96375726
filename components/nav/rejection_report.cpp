#include "rejection_report.hpp"

#include <spdlog/spdlog.h>

namespace gdnav::nav {

void RejectionReporting::finish(bool) {
    if (total() > 0) spdlog::info("[{}] {}", name(), counts(true));
}

std::string RejectionReporting::counts(bool summary) const {
    return fmt::format("{}rejected samples: {}", summary ? "end of run: " : "", count_details());
}

void RejectionReporting::report_counts(const framework::StepContext& ctx) {
    const std::uint64_t n = total();
    const bool due = !(n <= reported_ || (reported_ > 0 && ctx.t_s - t_reported_s_ < kPeriod_s));
    if (due) {
        reported_ = n;
        t_reported_s_ = ctx.t_s;
    }
    if (due || (ctx.last && n > 0)) publish_status(counts(ctx.last));
}

}  // namespace gdnav::nav
