// gdnav fault: injects a fault into a running run (docs/faults.md, "Live injection"). The clock stamps it with the
// step it takes effect at, every member applies it there, and <out>/faults.yaml records it for a re-run.
#include <unistd.h>

#include <chrono>
#include <cstdio>
#include <thread>

#include <fastdds/dds/subscriber/SampleInfo.hpp>
#include <spdlog/spdlog.h>
#include <yaml-cpp/yaml.h>

#include "commands.hpp"
#include "dds/dds_context.hpp"
#include "framework/lockstep.hpp"
#include "msgs/messages.hpp"
#include "framework/run_config.hpp"
#include "dds/security/security.hpp"
#include "framework/topic_types.hpp"

namespace gdnav::app {

namespace {

using namespace eprosima::fastdds::dds;

struct FaultArgs {
    int domain{0};
    std::uint64_t run_index{0};
    std::string target, kind, topic;
    double duration_s{0.0};
    std::vector<std::string> fields;  // NAME=VALUE (bias, noise) or NAME (nan)
    std::uint64_t steps{0};
    double p{0.0};
    double timeout_s{10.0};
    std::string security;  // DDS Security directory: the request is sent as identity `operator`
};

// The request's `faults:` entry as flow YAML (the clock validates it like a scenario's entry).
std::string entry_yaml(const FaultArgs& a, const CLI::App& sub) {
    YAML::Node e;
    e["target"] = a.target;
    e["kind"] = a.kind;
    if (!a.topic.empty()) e["topic"] = a.topic;
    if (sub.count("--for")) e["duration_s"] = a.duration_s;
    if (sub.count("--steps")) e["steps"] = a.steps;
    if (sub.count("--p")) e["p"] = a.p;
    for (const auto& f : a.fields) {
        const auto eq = f.find('=');
        if (a.kind == "nan") {
            e["fields"].push_back(f);
        } else if (eq == std::string::npos) {
            throw config::ConfigError("config error: --field '" + f + "': expected NAME=VALUE (e.g. h_m=5 or "
                                      "v_n_mps=[1,0,0])");
        } else {
            e["fields"][f.substr(0, eq)] = YAML::Load(f.substr(eq + 1));
        }
    }
    YAML::Emitter em;
    em.SetDoublePrecision(17);
    em << YAML::Flow << e;
    return em.c_str();
}

int send_fault(const FaultArgs& a, const std::string& entry) {
    runtime::register_gdnav_topics();
    runtime::DdsContext dds(a.domain, runtime::config_dir() / "dds/gdnav_profiles.xml", "gdnav.fault", a.security,
                            runtime::security::kOperatorIdentity);
    DataWriter* w = dds.writer(topics::kFaultRequest, runtime::message_ops<msg::FaultRequest>(),
                               runtime::kControlWriterProfile);
    DataReader* r = dds.reader(topics::kStatus, runtime::message_ops<msg::ComponentStatus>(),
                               runtime::kControlReaderProfile);
    const auto end = std::chrono::steady_clock::now() + std::chrono::duration<double>(a.timeout_s);
    PublicationMatchedStatus st;
    while (w->get_publication_matched_status(st), st.current_count == 0) {
        if (std::chrono::steady_clock::now() > end) {
            spdlog::error("no clock on DDS domain {} took the fault request within {:.0f} s (is a run going?)",
                          a.domain, a.timeout_s);
            return runtime::kExitStartup;
        }
        std::this_thread::sleep_for(std::chrono::milliseconds(20));
    }
    msg::FaultRequest req;
    req.run_id(a.run_index);
    req.request_id((static_cast<std::uint64_t>(getpid()) << 20) ^
                   static_cast<std::uint64_t>(std::chrono::steady_clock::now().time_since_epoch().count() & 0xfffff));
    req.fault(entry);
    w->write(&req);
    const std::string prefix = "fault " + std::to_string(req.request_id()) + " ";
    msg::ComponentStatus s;
    SampleInfo info;
    while (std::chrono::steady_clock::now() < end) {
        while (r->take_next_sample(&s, &info) == ReturnCode_t::RETCODE_OK) {
            if (!info.valid_data || s.member().to_string() != runtime::kClockName) continue;
            const std::string m = s.message().to_string();
            if (m.rfind(prefix, 0) != 0) continue;
            if (s.kind() == msg::STATUS_ERROR) {
                spdlog::error("{}", m);
                return runtime::kExitConfig;
            }
            spdlog::info("{}", m);
            return runtime::kExitOk;
        }
        std::this_thread::sleep_for(std::chrono::milliseconds(10));
    }
    spdlog::error("the clock on DDS domain {} did not answer the fault request within {:.0f} s", a.domain,
                  a.timeout_s);
    return runtime::kExitStartup;
}

}  // namespace

CLI::App* add_fault_command(CLI::App& app, CliContext& ctx, CommandRunner& run) {
    auto a = std::make_shared<FaultArgs>();
    auto* sub = app.add_subcommand("fault", "inject a fault into a running run (docs/faults.md)");
    sub->add_option("--domain", a->domain, "DDS domain of the run")->required()->check(CLI::Range(0, 232));
    sub->add_option("--run", a->run_index, "run index (default 0)");
    sub->add_option("--target", a->target, "member whose samples (or which, for kill) the fault hits")->required();
    sub->add_option("--kind", a->kind, "drop | freeze | bias | noise | delay | loss | nan | kill")
        ->required()
        ->check(CLI::IsMember({"drop", "freeze", "bias", "noise", "delay", "loss", "nan", "kill"}));
    sub->add_option("--topic", a->topic, "one output topic of the target (default: all)");
    sub->add_option("--for", a->duration_s, "duration in simulated seconds (default: to the end of the run)")
        ->check(CLI::Range(1e-6, 1e9));
    sub->add_option("--field", a->fields, "bias/noise: NAME=VALUE (e.g. h_m=5, v_n_mps=[1,0,0]); nan: NAME");
    sub->add_option("--steps", a->steps, "delay: steps late")->check(CLI::Range(1, 1000));
    sub->add_option("--p", a->p, "loss: probability of dropping each sample")->check(CLI::Range(0.0, 1.0));
    sub->add_option("--security", a->security, "DDS Security directory of a secure run (identity 'operator')");
    sub->add_option("--timeout", a->timeout_s, "seconds to wait for the clock's answer")->check(CLI::Range(0.1, 3600.0));
    run = [a, sub, &ctx]() {
        setup_logging("gdnav", ctx.log_level);
        return send_fault(*a, entry_yaml(*a, *sub));
    };
    return sub;
}

}  // namespace gdnav::app
