#pragma once
// The component model of gdnav (after Drake's systems and ROS 2 composition).
//
// A component is a small class that declares typed input and output ports (IDL message types) as members,
// implements `configure(cfg, run, stream)` once and a pure `step(ctx)` every 10-ms tick. It never sees DDS,
// processes or wall time: an executor (direct, or a DDS host) binds its inputs for step k, calls `step`, stamps
// and delivers its outputs. The same object therefore runs standalone, composed or directly.
//
//   class Plant : public Component {
//     Input<msg::ChainControl> u_{*this, "chain/control", Lag::Previous};   // feedback edge: step k-1
//     Output<msg::ChainState> x_{*this, "chain/state"};
//     void step(const StepContext& ctx) override { x_.value().x(...); }
//   };
//
// Inputs are bound to the sample of exactly step k (Lag::Same) or k-1 (Lag::Previous); an input whose producer was
// declared dead is `lost()` and never available again. At step 0 a Lag::Previous input is not available.
#include <cstdint>
#include <memory>
#include <string>
#include <string_view>
#include <vector>

#include "config/config.hpp"
#include "framework/compat.hpp"
#include "random/stream.hpp"
#include "msgs/message_ops.hpp"

namespace gdnav::framework {

enum class Lag : std::uint8_t { Same = 0, Previous = 1 };

// What every component knows about the run it belongs to.
struct RunInfo {
    std::uint64_t seed{1};
    std::uint64_t run_index{0};
    std::uint64_t steps{0};   // number of steps of the run (k = 0 .. steps-1)
    double dt_s{0.01};
    double t0_s{0.0};          // simulated time of step 0
    std::string out_dir;       // where recorders and reports write (empty: nowhere)
    [[nodiscard]] double time_of(std::uint64_t k) const { return t0_s + static_cast<double>(k) * dt_s; }
};

struct StepContext {
    std::uint64_t k{0};
    double t_s{0.0};
    double dt_s{0.01};
    bool last{false};
};

class Component;

class PortBase {
public:
    PortBase(Component& owner, std::string topic, const msg::MessageOps& ops);
    PortBase(const PortBase&) = delete;
    PortBase& operator=(const PortBase&) = delete;
    virtual ~PortBase() = default;
    [[nodiscard]] const std::string& topic() const { return topic_; }
    [[nodiscard]] const msg::MessageOps& ops() const { return *ops_; }

private:
    std::string topic_;
    const msg::MessageOps* ops_;
};

class InputBase : public PortBase {
public:
    InputBase(Component& owner, std::string topic, Lag lag, const msg::MessageOps& ops);
    [[nodiscard]] Lag lag() const { return lag_; }
    [[nodiscard]] bool available() const { return data_ != nullptr; }
    [[nodiscard]] bool lost() const { return lost_; }
    [[nodiscard]] const void* data_ptr() const { return data_; }
    // A member that uses only every N-th step of this input says so before it is hosted (an observer, e.g. the
    // live bridge): the executors then deliver only the steps of the stride framework/stride_policy.hpp takes for N
    // (a divisor of N, so every step the member uses is among them). 1: every step (the default).
    void set_stride(std::uint64_t n) { wanted_stride_ = n == 0 ? 1 : n; }
    [[nodiscard]] std::uint64_t wanted_stride() const { return wanted_stride_; }

protected:
    const void* data_{nullptr};

private:
    friend struct ExecutorAccess;  // binding and loss are the executors' (framework/executor_access.hpp)
    void bind(const void* data) { data_ = data; }
    void set_lost(bool lost) {
        lost_ = lost;
        if (lost) data_ = nullptr;
    }
    Lag lag_;
    bool lost_{false};
    std::uint64_t wanted_stride_{1};
};

class OutputBase : public PortBase {
public:
    OutputBase(Component& owner, std::string topic, const msg::MessageOps& ops);
    [[nodiscard]] virtual void* data() = 0;
};

template <class T>
class Input final : public InputBase {
public:
    Input(Component& owner, std::string topic, Lag lag = Lag::Same)
        : InputBase(owner, std::move(topic), lag, msg::message_ops<T>()) {}
    [[nodiscard]] const T& get() const { return *static_cast<const T*>(data_); }
    [[nodiscard]] const T* ptr() const { return static_cast<const T*>(data_); }
};

template <class T>
class Output final : public OutputBase {
public:
    Output(Component& owner, std::string topic) : OutputBase(owner, std::move(topic), msg::message_ops<T>()) {}
    [[nodiscard]] T& value() { return value_; }
    [[nodiscard]] const T& value() const { return value_; }
    [[nodiscard]] void* data() override { return &value_; }

private:
    T value_{};
};

class Component {
public:
    explicit Component(std::string name) : name_(std::move(name)) {}
    Component(const Component&) = delete;
    Component& operator=(const Component&) = delete;
    virtual ~Component() = default;

    [[nodiscard]] const std::string& name() const { return name_; }
    [[nodiscard]] const std::vector<InputBase*>& inputs() const { return inputs_; }
    [[nodiscard]] const std::vector<OutputBase*>& outputs() const { return outputs_; }

    // Reads the component's section of the run config (validated: call cfg.finish()) and draws per-run
    // quantities from `stream`, the component's own stream (seed, run index, component name).
    virtual void configure(const config::Config& cfg, const RunInfo& run, rnd::Stream& stream) = 0;
    // Computes step k from the bound inputs into the outputs.
    virtual void step(const StepContext& ctx) = 0;
    // Called once after the last step (flush files, final metrics). Default: nothing.
    virtual void finish(bool /*completed*/) {}
    // An observer (e.g. the live bridge) only looks at the run: it has no outputs and must never hold it. In the
    // direct layout nothing changes; a DDS host keeps it out of the clock's barrier (no StepDone; its status says
    // free_running, which for a member without outputs means exactly that, docs/protocol.md), reads its inputs with
    // best-effort readers (no acknowledgements, no resends), and skips a step whose sample was lost or arrived too
    // late for its inbox, counting it. Its inputs are still the samples of step k, so what it sees of step k is
    // what every other member saw.
    [[nodiscard]] virtual bool observer() const { return false; }

protected:
    // A mode change to publish on ComponentStatus (e.g. "GNSS lost"); the executor drains them after the step.
    void publish_status(std::string message) { status_.push_back(std::move(message)); }

private:
    friend class InputBase;
    friend class OutputBase;
    friend struct ExecutorAccess;
    std::string name_;
    std::vector<InputBase*> inputs_;
    std::vector<OutputBase*> outputs_;
    std::vector<std::string> status_;
};

}  // namespace gdnav::framework
