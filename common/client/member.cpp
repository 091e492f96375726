#include "gdnav/client/member.hpp"

#include <stdexcept>

#include <spdlog/sinks/stdout_color_sinks.h>
#include <spdlog/spdlog.h>

#include "dds/host/dds_host.hpp"
#include "framework/any_output.hpp"
#include "framework/lockstep.hpp"
#include "dds/process/process_signals.hpp"
#include "framework/run_config.hpp"
#include "framework/topic_types.hpp"

namespace gdnav::client {

// The member as a runtime component: its ports are the user's, its step calls the user's callback. The DDS host
// that runs it is the one every built-in member runs in (common/dds/host/dds_host.cpp and host/), so the protocol is the same.
class Member::Adapter final : public framework::Component {
public:
    using Component::Component;
    void configure(const config::Config&, const framework::RunInfo&, rnd::Stream&) override {}
    void step(const framework::StepContext& ctx) override {
        if (step_fn) step_fn(StepInfo{ctx.k, ctx.t_s, ctx.dt_s, ctx.last});
        for (auto& m : status) publish_status(std::move(m));
        status.clear();
    }
    void finish(bool completed) override {
        if (finish_fn) finish_fn(completed);
    }
    std::function<void(const StepInfo&)> step_fn;
    std::function<void(bool)> finish_fn;
    std::vector<std::string> status;
};

Member::Member(Options opt)
    : opt_(std::move(opt)), comp_(std::make_unique<Adapter>(opt_.name)), adapter_(comp_.get()) {
    if (opt_.name.empty() || opt_.name.size() > 63 || opt_.name.find_first_of(", \t") != std::string::npos)
        throw std::invalid_argument("member name '" + opt_.name + "': 1-63 characters, no commas or spaces");
    if (opt_.name == framework::kClockName) throw std::invalid_argument("member name 'clock' is reserved");
    if (opt_.domain_id < 0 || opt_.domain_id > 232)
        throw std::invalid_argument("DDS domain " + std::to_string(opt_.domain_id) + " out of range [0, 232]");
    framework::register_gdnav_topics();
}

Member::~Member() = default;

framework::Component& Member::component() {
    if (!comp_) throw std::logic_error("gdnav::client::Member: ports must be declared before run()");
    return *comp_;
}

const framework::InputBase& Member::input_any(const std::string& topic, Lag lag) {
    auto p = std::make_unique<framework::InputBase>(component(), topic, lag, framework::require_topic(topic));
    const framework::InputBase& ref = *p;
    inputs_.push_back(std::move(p));
    return ref;
}

framework::OutputBase& Member::output_any(const std::string& topic) {
    auto p = std::make_unique<framework::AnyOutput>(component(), topic, framework::require_topic(topic));
    framework::OutputBase& ref = *p;
    outputs_.push_back(std::move(p));
    return ref;
}

void Member::on_step(std::function<void(const StepInfo&)> fn) { static_cast<Adapter&>(component()).step_fn = std::move(fn); }

void Member::on_finish(std::function<void(bool)> fn) { static_cast<Adapter&>(component()).finish_fn = std::move(fn); }

void Member::publish_status(std::string message) {
    if (!adapter_) throw std::logic_error("gdnav::client::Member::publish_status(): the run is over");
    adapter_->status.push_back(std::move(message));
}

int Member::run() {
    if (!comp_) throw std::logic_error("gdnav::client::Member::run() may be called once");
    if (!spdlog::get(opt_.name)) setup_logging(opt_.name, opt_.log_level);
    dds::install_stop_signal_handlers();
    // What the host needs before the clock's CONFIGURE tells it the run's timing (steps, dt, t0, window).
    framework::RunConfig rc;
    rc.domain_id = opt_.domain_id;
    rc.domain_given = true;
    rc.info.run_index = opt_.run_id;
    rc.info.steps = UINT64_MAX;
    rc.startup_timeout_s = opt_.startup_timeout_s;
    rc.dds_profile =
        opt_.dds_profile.empty() ? framework::config_dir() / "dds" / "gdnav_profiles.xml" : opt_.dds_profile;
    if (!std::filesystem::is_regular_file(rc.dds_profile))
        throw std::invalid_argument("DDS profile " + rc.dds_profile.string() +
                                    ": no such file (set --dds-profile or GDNAV_CONFIG_DIR)");
    if (!opt_.security.empty()) rc.security_dir = std::filesystem::absolute(opt_.security);
    spdlog::info("member '{}' joining DDS domain {}, run id {}{} ({} inputs, {} outputs)", opt_.name, opt_.domain_id,
                 opt_.run_id, opt_.free_running ? ", free-running" : "", inputs_.size(), outputs_.size());
    std::vector<std::unique_ptr<framework::Component>> members;
    members.push_back(std::move(comp_));
    dds::HostOptions ho;
    ho.free_running = opt_.free_running;
    dds::DdsHost host(rc, std::move(members), ho);
    const int code = host.run();
    adapter_ = nullptr;  // destroyed with the host
    if (code == framework::kExitOk)
        spdlog::info("member '{}': run complete", opt_.name);
    else if (const std::string why = host.abort_reason(); !why.empty())
        spdlog::error("member '{}': ended with exit code {}: the clock aborted the run: {}", opt_.name, code, why);
    else
        spdlog::error("member '{}': ended with exit code {}", opt_.name, code);
    return code;
}

void setup_logging(const std::string& name, const std::string& level) {
    auto logger = spdlog::get(name);
    if (!logger) logger = spdlog::stderr_color_mt(name);
    spdlog::set_default_logger(logger);
    spdlog::set_pattern("[%H:%M:%S.%e] [%n] %^%l%$: %v");
    spdlog::set_level(spdlog::level::from_str(level));
}

}  // namespace gdnav::client
