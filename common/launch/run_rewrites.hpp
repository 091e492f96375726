#pragma once
// Rewrites of a resolved run configuration requested on `gdnav run`'s command line:
//   --record TOPICS            add a `recorder` member recording these topics (or `all`) to <out>/record; the keyword
//                              `viewer` adds its viewer channels (docs/viewing.md), e.g. --record default,viewer
//   --replay RUN_DIR --topics  publish the listed topics from RUN_DIR's recording with a `replay` member and drop
//                              the members whose outputs are all replayed (see docs/replay.md)
//   --live [PORT]              add a `live` member (components/live) serving the run to Foxglove over WebSocket
//                              (--live-bind, --live-decimation, --live-topics; docs/viewing.md "Live view")
// The result is validated like any run configuration (ConfigError with file, key and allowed values).
#include <cstdint>
#include <string>
#include <vector>

#include "framework/registry.hpp"
#include "framework/run_config.hpp"

namespace gdnav::launch {

struct RunRewrites {
    std::vector<std::string> record;         // topic names (short "ImuSample" or full "gdnav/ImuSample"), or "all"
    std::string replay_dir;                  // a finished run's directory (holds run.yaml and record/)
    std::vector<std::string> replay_topics;  // topics to replay from replay_dir
    bool live{false};                        // --live given
    std::string live_port;                   // --live PORT ("" = the member's default, 8765)
    std::string live_bind;                   // --live-bind ADDR ("" = the member's default, 127.0.0.1)
    std::uint64_t live_decimation{0};        // --live-decimation N (0 = not given: every step)
    std::vector<std::string> live_topics;    // --live-topics (empty = every data topic and the viewer channels)
    bool keep_domain{false};                 // the run's domain_id was chosen for this run (--domain, or the
                                             // --scenario file's): a replay keeps it instead of the recorded run's
    [[nodiscard]] bool empty() const {
        return record.empty() && replay_dir.empty() && replay_topics.empty() && !live && live_bind.empty() &&
               live_decimation == 0 && live_topics.empty();
    }
};

// Applies the rewrites to `rc` (already resolved: generator run, overrides applied) and returns the new config.
framework::RunConfig apply_run_rewrites(const framework::RunConfig& rc, const RunRewrites& rw,
                                      const framework::ComponentRegistry& reg);

}  // namespace gdnav::launch
