#pragma once
// `gdnav fault`: a fault injected into a running run (docs/faults.md, "Live injection"). The request goes to the
// run's clock on its DDS domain; the clock stamps it with the step it takes effect at, every member applies it
// there, and <out>/faults.yaml records it for a re-run.
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

namespace gdnav::launch::fault {

struct FaultRequestSpec {
    int domain{0};
    std::uint64_t run_index{0};
    std::string target, kind, topic;
    std::optional<double> duration_s;         // simulated seconds (absent: to the end of the run)
    std::vector<std::string> fields;          // NAME=VALUE (bias, noise) or NAME (nan)
    std::optional<std::uint64_t> steps;       // delay: steps late
    std::optional<double> p;                  // loss: probability of dropping each sample
    double timeout_s{10.0};                   // to wait for the clock's answer
    std::string security;  // DDS Security directory: the request is sent as identity `operator`
};

// The request's `faults:` entry as flow YAML (the clock validates it like a scenario's entry). Throws
// config::ConfigError (one line naming the --field value) for a malformed field.
std::string fault_entry_yaml(const FaultRequestSpec& a);

// Sends the entry and waits for the clock's answer: kExitOk when it took the fault, kExitConfig when it refused it
// (its message logged), kExitStartup when no clock matched or answered within timeout_s.
int send_fault_request(const FaultRequestSpec& a, const std::string& entry);

}  // namespace gdnav::launch::fault
