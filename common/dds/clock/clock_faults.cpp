// Faults requested while the run flies (gdnav fault) and <out>/faults.yaml (part of clock.cpp's Clock::Impl).
#include "dds/clock/clock_impl.hpp"

#include <filesystem>

#include <fastdds/dds/subscriber/SampleInfo.hpp>
#include <spdlog/spdlog.h>
#include <yaml-cpp/yaml.h>

#include "dds/process/run_cause.hpp"
#include "files/write_error.hpp"
#include "framework/graph.hpp"

namespace gdnav::dds {

using namespace eprosima::fastdds::dds;

// A fault injected live (gdnav fault): stamped with the first step no member can have reached, validated, sent
// to every member; the run waits at the current step until all live members have adopted it.
void Clock::Impl::read_fault_requests(double now) {
    SampleInfo info;
    while (fault_reader->take_next_sample(&fault_in, &info) == ReturnCode_t::RETCODE_OK) {
        if (!this_run(info, fault_in, "a fault sender", "FaultRequest")) continue;
        const std::string id = std::to_string(fault_in.request_id());
        const std::string text = fault_in.fault().to_string();
        std::string error;
        if (phase != Phase::Running) error = "the run is not running yet (wait for step 0)";
        std::uint64_t at = current + rc.window_steps + 2;
        try {
            const YAML::Node e = YAML::Load(text);
            if (e.IsMap() && e["kind"] && e["kind"].as<std::string>() == "delay" && e["steps"])
                at += e["steps"].as<std::uint64_t>();  // the members' history of the delayed samples starts now
        } catch (const std::exception&) {
            // malformed: add_live names the problem
        }
        if (error.empty() && at >= rc.info.steps) error = "the run ends before step " + std::to_string(at);
        if (error.empty()) {
            try {
                std::map<std::string, framework::faults::MemberPorts> ports;
                for (const Member* m : table) {
                    auto& p = ports[m->name];
                    p.outputs = framework::split_topics(m->outputs);
                    p.external = rc.is_external(m->name) || m->free;
                }
                const framework::faults::Fault& f = schedule.add_live(text, at, rc.info, ports);
                ++faults_version;
                adopting = true;
                adopt_start_s = now;
                send_control(msg::RUN_FAULTS, "");
                write_faults();
                const std::string what = "fault " + id + " accepted: " + f.describe() + " (step " +
                                         std::to_string(f.from_step) + ")";
                spdlog::warn("{}", what);
                send_clock_status(msg::STATUS_MODE, what);
                continue;
            } catch (const std::exception& e) {
                error = e.what();
            }
        }
        spdlog::error("fault {} refused: {}", id, error);
        send_clock_status(msg::STATUS_ERROR, "fault " + id + " refused: " + error);
    }
}

// <out>/faults.yaml: the schedule as applied (the run config's faults and those injected live, with the step
// they took effect at), for `gdnav run --faults FILE` to reproduce the run.
void Clock::Impl::write_faults() const {
    if (rc.out_dir.empty() || schedule.empty()) return;
    std::error_code ec;
    std::filesystem::create_directories(rc.out_dir, ec);
    try {  // whole or not at all (docs/runtime.md, "Exit codes")
        files::write_whole(std::filesystem::path(rc.out_dir) / "faults.yaml",
                           "# The fault schedule of this run as applied (scheduled and injected live).\n"
                           "# Reproduce the run: gdnav run --scenario <run.yaml> --faults <this file> (any layout)\n" +
                               schedule.to_yaml() + "\n");
    } catch (const files::WriteError& e) {
        spdlog::error("{}", e.what());
        tell_launcher(e.what());
    }
}

}  // namespace gdnav::dds
