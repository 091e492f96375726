#include "dds/foreign_runs.hpp"

#include <random>

#include <spdlog/spdlog.h>

namespace gdnav::dds {

std::uint64_t draw_run_token() {
    std::random_device rd;
    std::uint64_t t = 0;
    while (t == 0) t = (static_cast<std::uint64_t>(rd()) << 32) ^ static_cast<std::uint64_t>(rd());
    return t;
}

std::string token_text(std::uint64_t token) { return fmt::format("0x{:016x}", token); }

void ForeignRuns::note(std::uint64_t token, const std::string& source, const char* what) {
    ++count_;
    if (!sources_.insert(token_text(token) + " " + source).second) return;
    spdlog::warn("{}ignoring control messages of another run on this DDS domain (token {}, from {}, first: {}); "
                 "they are counted, not used",
                 who_.empty() ? "" : who_ + ": ", token_text(token), source, what);
}

void ForeignRuns::report() const {
    if (count_ == 0) return;
    spdlog::info("{}{} control message(s) of other runs ignored ({} source(s))", who_.empty() ? "" : who_ + ": ",
                 count_, sources_.size());
}

}  // namespace gdnav::dds
