#include "launch/fault/fault_request.hpp"

#include <unistd.h>

#include <chrono>
#include <thread>

#include <fastdds/dds/subscriber/SampleInfo.hpp>
#include <spdlog/spdlog.h>
#include <yaml-cpp/yaml.h>

#include "config/config.hpp"
#include "dds/dds_context.hpp"
#include "dds/security/security.hpp"
#include "launch/pki/identity_check.hpp"
#include "framework/lockstep.hpp"
#include "framework/run_config.hpp"
#include "framework/topic_types.hpp"
#include "msgs/messages.hpp"

namespace gdnav::launch::fault {

using namespace eprosima::fastdds::dds;

std::string fault_entry_yaml(const FaultRequestSpec& a) {
    YAML::Node e;
    e["target"] = a.target;
    e["kind"] = a.kind;
    if (!a.topic.empty()) e["topic"] = a.topic;
    if (a.duration_s) e["duration_s"] = *a.duration_s;
    if (a.steps) e["steps"] = *a.steps;
    if (a.p) e["p"] = *a.p;
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

int send_fault_request(const FaultRequestSpec& a, const std::string& entry) {
    framework::register_gdnav_topics();
    if (!a.security.empty()) pki::check_identity(a.security, dds::security::kOperatorIdentity);
    dds::DdsContext dds(a.domain, framework::config_dir() / "dds/gdnav_profiles.xml", "gdnav.fault", a.security,
                            dds::security::kOperatorIdentity);
    DataWriter* w = dds.writer(topics::kFaultRequest, msg::message_ops<msg::FaultRequest>(),
                               dds::kControlWriterProfile);
    DataReader* r = dds.reader(topics::kStatus, msg::message_ops<msg::ComponentStatus>(),
                               dds::kControlReaderProfile);
    const auto end = std::chrono::steady_clock::now() + std::chrono::duration<double>(a.timeout_s);
    PublicationMatchedStatus st;
    while (w->get_publication_matched_status(st), st.current_count == 0) {
        if (std::chrono::steady_clock::now() > end) {
            spdlog::error("no clock on DDS domain {} took the fault request within {:.0f} s (is a run going?)",
                          a.domain, a.timeout_s);
            return framework::kExitStartup;
        }
        std::this_thread::sleep_for(std::chrono::milliseconds(20));
    }
    // The request carries the run's token (the clock ignores another): learnt from the clock's heartbeat.
    msg::ComponentStatus s;
    SampleInfo info;
    std::uint64_t token = 0;
    while (token == 0) {
        while (token == 0 && r->take_next_sample(&s, &info) == ReturnCode_t::RETCODE_OK)
            if (info.valid_data && s.member().to_string() == framework::kClockName && s.run_id() == a.run_index)
                token = s.run_token();
        if (token != 0) break;
        if (std::chrono::steady_clock::now() > end) {
            spdlog::error("no clock of run id {} on DDS domain {} within {:.0f} s (is a run going?)", a.run_index,
                          a.domain, a.timeout_s);
            return framework::kExitStartup;
        }
        std::this_thread::sleep_for(std::chrono::milliseconds(20));
    }
    msg::FaultRequest req;
    req.run_id(a.run_index);
    req.run_token(token);
    req.request_id((static_cast<std::uint64_t>(getpid()) << 20) ^
                   static_cast<std::uint64_t>(std::chrono::steady_clock::now().time_since_epoch().count() & 0xfffff));
    req.fault(entry);
    w->write(&req);
    const std::string prefix = "fault " + std::to_string(req.request_id()) + " ";
    while (std::chrono::steady_clock::now() < end) {
        while (r->take_next_sample(&s, &info) == ReturnCode_t::RETCODE_OK) {
            if (!info.valid_data || s.member().to_string() != framework::kClockName || s.run_token() != token) continue;
            const std::string m = s.message().to_string();
            if (m.rfind(prefix, 0) != 0) continue;
            if (s.kind() == msg::STATUS_ERROR) {
                spdlog::error("{}", m);
                return framework::kExitConfig;
            }
            spdlog::info("{}", m);
            return framework::kExitOk;
        }
        std::this_thread::sleep_for(std::chrono::milliseconds(10));
    }
    spdlog::error("the clock on DDS domain {} did not answer the fault request within {:.0f} s", a.domain,
                  a.timeout_s);
    return framework::kExitStartup;
}

}  // namespace gdnav::launch::fault
