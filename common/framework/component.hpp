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
#include "random/stream.hpp"
#include "msgs/message_ops.hpp"

namespace gdnav::runtime {

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
    PortBase(Component& owner, std::string topic, const MessageOps& ops);
    PortBase(const PortBase&) = delete;
    PortBase& operator=(const PortBase&) = delete;
    virtual ~PortBase() = default;
    [[nodiscard]] const std::string& topic() const { return topic_; }
    [[nodiscard]] const MessageOps& ops() const { return *ops_; }

private:
    std::string topic_;
    const MessageOps* ops_;
};

class InputBase : public PortBase {
public:
    InputBase(Component& owner, std::string topic, Lag lag, const MessageOps& ops);
    [[nodiscard]] Lag lag() const { return lag_; }
    [[nodiscard]] bool available() const { return data_ != nullptr; }
    [[nodiscard]] bool lost() const { return lost_; }
    [[nodiscard]] const void* data_ptr() const { return data_; }
    // Stride: the member reads only the samples of steps k with k % stride == 0 (k of the sample: k - 1 for
    // Lag::Previous); at the other steps the input is absent and never waited for. Set before the member is hosted.
    // Over DDS the reader asks the producers' writers to send only those steps (a writer-side content filter,
    // dds/filters/stride_filter.hpp), so the member does not receive the samples between; an observer's input at stride
    // 10 reads the producers' decimated mirror of the topic instead where they write one (dds/host/mirror.hpp).
    // set_stride(N) (a member that uses every N-th step) takes the largest divisor of N in [kMinStride, kMaxStride],
    // or 1 (every sample) when N has none. Why these bounds: with Fast DDS 2.9.1 a writer that filters for a reader
    // still sends it GAP/HEARTBEAT traffic for the skipped samples; beyond a stride of about 10 that traffic
    // outweighs the samples saved, and at stride 2 it costs more than sending everything (figures:
    // docs/notes/runtime-measurements.md, "Which strides pay").
    static constexpr std::uint64_t kMinStride = 4;
    static constexpr std::uint64_t kMaxStride = 10;
    [[nodiscard]] std::uint64_t stride() const { return stride_; }
    void set_stride(std::uint64_t n) {
        stride_ = 1;
        for (std::uint64_t d = n < kMaxStride ? n : kMaxStride; d >= kMinStride; --d)
            if (n % d == 0) {
                stride_ = d;
                break;
            }
    }
    [[nodiscard]] bool on_stride(std::uint64_t sample_step) const { return stride_ == 1 || sample_step % stride_ == 0; }
    // Executor side.
    void bind(const void* data) { data_ = data; }
    void mark_lost() { lost_ = true; data_ = nullptr; }
    // A scheduled fault: the producer is killed at this step (true) or alive again after a restart (false).
    void set_lost(bool lost) {
        lost_ = lost;
        if (lost) data_ = nullptr;
    }

protected:
    const void* data_{nullptr};

private:
    Lag lag_;
    bool lost_{false};
    std::uint64_t stride_{1};  // 1 or kMinStride..kMaxStride
};

class OutputBase : public PortBase {
public:
    OutputBase(Component& owner, std::string topic, const MessageOps& ops);
    [[nodiscard]] virtual void* data() = 0;
};

template <class T>
class Input final : public InputBase {
public:
    Input(Component& owner, std::string topic, Lag lag = Lag::Same)
        : InputBase(owner, std::move(topic), lag, message_ops<T>()) {}
    [[nodiscard]] const T& get() const { return *static_cast<const T*>(data_); }
    [[nodiscard]] const T* ptr() const { return static_cast<const T*>(data_); }
};

template <class T>
class Output final : public OutputBase {
public:
    Output(Component& owner, std::string topic) : OutputBase(owner, std::move(topic), message_ops<T>()) {}
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
    // Mode changes a component wants published on ComponentStatus (e.g. "GNSS lost"); the executor drains it.
    std::vector<std::string>& pending_status() { return status_; }

protected:
    void publish_status(std::string message) { status_.push_back(std::move(message)); }

private:
    friend class InputBase;
    friend class OutputBase;
    std::string name_;
    std::vector<InputBase*> inputs_;
    std::vector<OutputBase*> outputs_;
    std::vector<std::string> status_;
};

}  // namespace gdnav::runtime
