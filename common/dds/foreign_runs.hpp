#pragma once
// A run owns its DDS domain (docs/protocol.md, "Run token"): the clock draws a run token at start and every control
// message of the run carries it. Control messages of another token come from another run on the same domain; the
// clock and the members ignore them, count them, and log one line per source (not one per message).
#include <cstdint>
#include <set>
#include <string>

#include "dds/compat.hpp"

namespace gdnav::dds {

// A fresh run token from the operating system's entropy (std::random_device), never 0. It identifies the run on the
// wire only: it must not reach a recorded topic, a digest or metrics.yaml (runs stay bit-reproducible).
std::uint64_t draw_run_token();
// "0x" and 16 hex digits.
std::string token_text(std::uint64_t token);

class ForeignRuns {
public:
    explicit ForeignRuns(std::string who = "") : who_(std::move(who)) {}
    // One control message of another run: counted; the first from `source` (a host, or a topic) logs one line.
    void note(std::uint64_t token, const std::string& source, const char* what);
    // Counted without a line (a clock claiming its domain says it once, naming the other run).
    void count_quietly() { ++count_; }
    [[nodiscard]] std::uint64_t count() const { return count_; }
    // At the end of the run: one line with the count, when there were any.
    void report() const;

private:
    std::string who_;
    std::set<std::string> sources_;
    std::uint64_t count_{0};
};

}  // namespace gdnav::dds
