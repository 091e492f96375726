#pragma once
// gdnav::client — write a lockstep member of a gdnav run outside gdnav (your own filter, controller, a bridge to
// hardware) in a few dozen lines. The member joins a run started with `gdnav run --external NAME` (docs/external.md)
// and speaks the lockstep protocol of docs/protocol.md for you:
//
//   #include <gdnav/client/member.hpp>
//   int main(int argc, char** argv) {
//       auto opt = gdnav::client::Options::from_args(argc, argv, "nav_att");   // --domain D --run I ...
//       gdnav::client::Member m(opt);
//       auto& imu = m.input<gdnav::msg::ImuSample>("gdnav/ImuSample");
//       auto& pos = m.input<gdnav::msg::PositionEstimate>("gdnav/PositionEstimate", gdnav::client::Lag::Previous);
//       auto& att = m.output<gdnav::msg::AttitudeEstimate>("gdnav/AttitudeEstimate");
//       m.on_step([&](const gdnav::client::StepInfo& s) {
//           if (!imu.available()) return;               // e.g. its producer was declared dead
//           att.value().q_nb(...);                      // published, stamped with (run id, s.k, s.t_s), after return
//       });
//       return m.run();                                 // 0 when the run completed; see exit codes below
//   }
//
// Inputs of step k are bound before the callback: Lag::Same = the sample of step k, Lag::Previous = of step k-1 (not
// available at k = 0). Every output is published after every step (its value persists between steps). A member
// declared with `free_running` is not in the clock's barrier and its inputs are the newest samples (zero-order hold).
// Exit codes of run(): 0 completed, 3 aborted by the clock, 4 lost the clock, 5 no clock / protocol mismatch,
// 130 interrupted (SIGINT/SIGTERM).
#include <cstdint>
#include <filesystem>
#include <functional>
#include <memory>
#include <string>
#include <vector>

#include "framework/component.hpp"
#include "msgs/messages.hpp"

namespace gdnav::client {

using framework::Lag;
template <class T>
using In = framework::Input<T>;  // available(), lost(), get()
template <class T>
using Out = framework::Output<T>;  // value()

struct Options {
    std::string name;                    // member name: must match `--external NAME` of the run
    int domain_id{0};                    // DDS domain of the run (printed by `gdnav run`)
    std::uint64_t run_id{0};             // run index of the run (gdnav run --run I; 0 by default)
    bool free_running{false};            // not in the barrier; inputs are the newest samples (HIL)
    std::filesystem::path dds_profile;   // Fast DDS XML; empty = <config dir>/dds/gdnav_profiles.xml
    std::filesystem::path security;      // DDS Security directory (gdnav pki init --member NAME=...); identity = name
    double startup_timeout_s{120.0};     // wait this long for the clock's member table, then exit 5
    std::string log_level{"info"};

    // Reads --name NAME, --domain D, --run I, --free-running, --dds-profile FILE, --startup-timeout S,
    // --log-level L (and --help). Unknown or malformed arguments throw std::invalid_argument with a one-line message.
    // Without a flag, a setting comes from the environment gdnav gives the members it starts (run.members):
    // GDNAV_MEMBER (name), GDNAV_DOMAIN, GDNAV_RUN, GDNAV_SECURITY, GDNAV_DDS_PROFILE; else from default_name and
    // the defaults above.
    // `extra` receives arguments that start with "--x-" (left for the member's own options) when not null.
    static Options from_args(int argc, const char* const* argv, std::string default_name,
                             std::vector<std::string>* extra = nullptr);
    static std::string usage(const std::string& program);
};

struct StepInfo {
    std::uint64_t k{0};    // step index
    double t_s{0.0};       // simulated time of step k [s]
    double dt_s{0.01};     // step length [s]
    bool last{false};      // the run's final step
};

class Member {
public:
    explicit Member(Options opt);
    ~Member();
    Member(const Member&) = delete;
    Member& operator=(const Member&) = delete;

    [[nodiscard]] const Options& options() const { return opt_; }

    // Typed ports (declare before run()). The topic names are "gdnav/<Type>" (docs/protocol.md).
    template <class T>
    const In<T>& input(const std::string& topic, Lag lag = Lag::Same) {
        auto p = std::make_unique<In<T>>(component(), topic, lag);
        const In<T>& ref = *p;
        inputs_.push_back(std::move(p));
        return ref;
    }
    template <class T>
    Out<T>& output(const std::string& topic) {
        auto p = std::make_unique<Out<T>>(component(), topic);
        Out<T>& ref = *p;
        outputs_.push_back(std::move(p));
        return ref;
    }
    // Untyped ports by topic name (type from the topic table; used by the Python bindings). Throws
    // std::invalid_argument naming the known topics when the topic is unknown.
    const framework::InputBase& input_any(const std::string& topic, Lag lag = Lag::Same);
    framework::OutputBase& output_any(const std::string& topic);

    void on_step(std::function<void(const StepInfo&)> fn);
    void on_finish(std::function<void(bool completed)> fn);
    // Publishes a mode change or notice on ComponentStatus (shown in the clock's log), after the current step
    // (callable before and during run(), e.g. from the step callback).
    void publish_status(std::string message);

    // Joins the run and steps until STOP / ABORT / lost clock / SIGINT. Returns the exit code (see above).
    int run();

private:
    framework::Component& component();
    class Adapter;
    Options opt_;
    std::unique_ptr<Adapter> comp_;
    Adapter* adapter_{nullptr};  // comp_, also while the host owns it during run()
    std::vector<std::unique_ptr<framework::InputBase>> inputs_;
    std::vector<std::unique_ptr<framework::OutputBase>> outputs_;
};

// spdlog to stderr named after the member (call once, before run(); Member::run() does it if nothing is set up).
void setup_logging(const std::string& name, const std::string& level);

}  // namespace gdnav::client
