#pragma once
// Scheduled faults of a run (docs/faults.md): the `faults:` list of a run config or scenario, parsed and validated.
//
//   faults:
//     - {at_s: 100, until_s: 300, target: sensors_gnss, kind: drop}
//     - {at_s: 150, target: sensors_air, topic: gdnav/AirDataSample, kind: bias, fields: {tas_mps: 2.0}}
//     - {at_s: 50, until_s: 60, target: sensors_mag, kind: noise, fields: {b_b_nT: [300, 300, 300]}}
//     - {at_s: 10, until_s: 20, target: sensors_inertial, kind: delay, steps: 5}
//     - {at_s: 10, target: sensors_gnss, kind: loss, p: 0.3}
//     - {at_s: 20, until_s: 21, target: sensors_air, kind: nan, fields: [tas_mps]}   # a corrupt sample
//     - {at_s: 200, until_s: 260, target: nav_att, kind: kill}      # until_s: restarts at 260 s
//     - {at_s: 200, target: nav_att, kind: kill}
//     - {at_s: 260, target: nav_att, kind: restart}                   # the same as the until_s above
//
// A fault acts on the samples a target member publishes (all its output topics, or `topic`), from the first step
// with t >= at_s to the last step with t < until_s (to the end of the run without until_s). The runtime applies it
// where the samples are delivered (framework/faults/input_faults.hpp), so every consumer in every layout sees the
// same faulted samples, and a run with faults is as reproducible as one without. `kill` stops the member itself: it
// is not stepped, publishes nothing and its consumers see its inputs lost; `restart` (or until_s of a kill)
// creates the member anew at that step boundary (configured as at the start: its state starts over).
// Times are converted to steps with the run's t0_s and dt_s: step(t) = ceil((t - t0_s) / dt_s - 1e-9).
#include <cstdint>
#include <deque>
#include <map>
#include <string>
#include <vector>

#include "config/config.hpp"
#include "framework/compat.hpp"
#include "framework/component.hpp"

namespace gdnav::framework::faults {

// Rejoin: not written by users; the clock records with it that a member declared dead came back (gdnav component
// --rejoin) and is stepped again from at_s.
enum class Kind : std::uint8_t { Drop, Freeze, Bias, Noise, Delay, Loss, Kill, Restart, Nan, Rejoin };
const char* kind_name(Kind k);

struct Fault {
    std::size_t index{0};      // position in the list (names its random stream)
    Kind kind{Kind::Drop};
    std::string target;        // member name
    std::string topic;         // one output topic of the target; empty: all of them
    double at_s{0.0};
    double until_s{0.0};       // meaningful when has_until
    bool has_until{false};
    std::uint64_t from_step{0};
    std::uint64_t until_step{UINT64_MAX};  // exclusive
    // bias: field -> offsets; noise: field -> standard deviations (one value per element, or one for all);
    // nan: field -> {} (set to NaN).
    std::vector<std::pair<std::string, std::vector<double>>> fields;
    std::uint64_t delay_steps{0};  // delay
    double probability{0.0};       // loss
    [[nodiscard]] bool active(std::uint64_t step) const { return step >= from_step && step < until_step; }
    [[nodiscard]] bool applies_to(const std::string& producer, const std::string& t) const {
        return producer == target && (topic.empty() || topic == t);
    }
    [[nodiscard]] std::string describe() const;  // "drop of sensors_gnss from 100 s to 300 s"
};

// What the schedule needs to know of the run's members to validate faults against them.
struct MemberPorts {
    std::vector<std::string> outputs;  // topic names
    bool external{false};              // run outside gdnav (its outputs are unknown before it joins)
};

class FaultSchedule {
public:
    FaultSchedule() = default;
    // Parses the `faults` sequence of `doc` (absent: no faults). Throws config::ConfigError naming the key of the
    // first bad entry (faults[i].key) and what is allowed.
    static FaultSchedule parse(const config::Config& doc, const RunInfo& run);
    // Re-reads the schedule from the text of to_yaml() (as carried by the clock's CONFIGURE).
    static FaultSchedule from_yaml(const std::string& text, const RunInfo& run);
    // Flow-style YAML of the list ("" when empty): the clock's CONFIGURE carries it to every member.
    [[nodiscard]] std::string to_yaml() const;

    // Checks targets, topics and fields against the members of the run; throws config::ConfigError.
    void validate(const std::map<std::string, MemberPorts>& members, const std::string& origin) const;

    // A fault injected into a running run (gdnav fault): one `faults:` entry as flow YAML without at_s, taking
    // effect at step `at_step` (a duration_s key sets until_s = at_s + duration_s; restart is not allowed live).
    // Validated like the file's entries; throws config::ConfigError. Returns the new fault.
    const Fault& add_live(const std::string& entry_yaml, std::uint64_t at_step, const RunInfo& run,
                          const std::map<std::string, MemberPorts>& members);
    // Appends the faults of `longer` beyond this schedule's (the clock's FAULTS after a live injection). Faults
    // already held keep their addresses. Returns the index of the first new fault.
    std::size_t adopt(const FaultSchedule& longer);

    [[nodiscard]] bool empty() const { return faults_.empty(); }
    [[nodiscard]] std::size_t size() const { return faults_.size(); }
    [[nodiscard]] const std::deque<Fault>& faults() const { return faults_; }
    // Faults acting on samples of `topic` published by `producer` (kill windows included), from index `first`.
    [[nodiscard]] std::vector<const Fault*> on(const std::string& producer, const std::string& topic,
                                               std::size_t first = 0) const;
    // True when `member` is killed at step k (between a kill and its restart).
    [[nodiscard]] bool killed(const std::string& member, std::uint64_t k) const;
    // True when `member` is created anew at step k (the end of one of its kill windows, inside the run).
    [[nodiscard]] bool restarts_at(const std::string& member, std::uint64_t k) const;
    // First step >= k at which `member` is alive again (UINT64_MAX: never).
    [[nodiscard]] std::uint64_t alive_again(const std::string& member, std::uint64_t k) const;

private:
    std::deque<Fault> faults_;  // kills carry their restart step in until_step; restart entries are kept too
};

}  // namespace gdnav::framework::faults
