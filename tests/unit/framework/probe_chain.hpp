#pragma once
// The framework tests' chain scenario (tests/chain components) and two probe components on topic probe/a: Source
// writes the step index, Sink records what its input held at each step (-1 when nothing was available).
#include <string>
#include <vector>

#include "chain_components.hpp"
#include "framework/component.hpp"

namespace gdnav::framework::test {

// A probe that records what it saw on its inputs.
class Source final : public Component {
public:
    using Component::Component;
    void configure(const config::Config&, const RunInfo&, rnd::Stream&) override {}
    void step(const StepContext& ctx) override { out_.value().u_mps2(static_cast<double>(ctx.k)); }
    Output<testchain::ChainControl> out_{*this, "probe/a"};
};

class Sink final : public Component {
public:
    Sink(std::string n, Lag lag) : Component(std::move(n)), in_(*this, "probe/a", lag) {}
    void configure(const config::Config&, const RunInfo&, rnd::Stream&) override {}
    void step(const StepContext&) override { seen.push_back(in_.available() ? in_.get().u_mps2() : -1.0); }
    Input<testchain::ChainControl> in_;
    std::vector<double> seen;
};

inline const char* kChain = R"(
run: {seed: 5, steps: 50}
components:
  chain_plant: {type: chain_plant, sigma_w_mps2: 0.5, damping_per_s: 0.2, x0_m: 3.0}
  chain_sensor: {type: chain_sensor, sigma_m: 0.1}
  chain_filter: {type: chain_filter, alpha: 0.2, beta: 0.02}
  chain_controller: {type: chain_controller, kp: 1.0, kd: 1.5, target_m: 0.0}
)";

}  // namespace gdnav::framework::test
