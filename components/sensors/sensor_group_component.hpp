#pragma once
// The component shape shared by the five sensor groups (sensor_components.cpp): Truth(k) -> the group's measurement
// topic. The component loads the suite with the run's timing, lets the group apply its section's overrides,
// configures the group's model on the component's stream and, for a group that aligns, runs the alignment once at
// the first measured step and publishes it with every later sample. A group states only what differs, as a struct:
//
//   using Model, Sample;                    the error model and the message it writes
//   static constexpr const char* kTopic;    the measurement topic
//   static auto& params(SensorSuiteParams&);                         the model's parameters in the suite
//   static void apply_overrides(const config::Config&, SensorSuiteParams&);  the section's keys
//   static auto truth(const msg::Truth&);                            the model's truth input
//   static void write(const Measurement&, Sample&);                  the measurement into the message
//   optionally static void align(const AlignmentErrors&, const msg::Truth&, const Measurement&, rnd::Stream&, Sample&);
#include <filesystem>
#include <string>

#include "framework/component.hpp"
#include "framework/run_config.hpp"
#include "msgs/messages.hpp"
#include "gnc/alignment.hpp"
#include "sensors/model/suite.hpp"

namespace gdnav::sensors {

// The suite file named in a sensor component's section (relative to config/).
inline std::filesystem::path suite_file(const config::Config& cfg) {
    return cfg.get_file("suite", "sensors/suite.yaml", framework::config_dir());
}

// Grade override: re-reads one group's grade file from the suite's folder when the section names one under `key`.
template <class Grade, class Parse>
void override_grade(const config::Config& cfg, const char* key, const char* group, Grade& grade, std::string& name,
                    Parse parse) {
    if (!cfg.has(key)) return;
    grade = parse(load_grade(cfg, key, suite_file(cfg).parent_path(), group, name));
}

template <class Group>
class SensorGroupComponent final : public framework::Component {
public:
    using Component::Component;
    void configure(const config::Config& cfg, const framework::RunInfo& run, rnd::Stream& stream) override {
        SensorSuiteParams s = load_sensor_suite(suite_file(cfg));
        s.inertial.dt_s = run.dt_s;
        s.mag.dt_s = run.dt_s;
        s.gnss.dt_s = run.dt_s;
        s.gnss.t0_s = run.t0_s;
        Group::apply_overrides(cfg, s);
        model_.configure(Group::params(s), stream);
        if constexpr (kAligns) {
            align_errors_ = s.alignment;
            align_stream_ = stream.child("alignment");
            aligned_ = false;
        }
    }
    void step(const framework::StepContext& ctx) override {
        if (!truth_.available()) return;  // no truth sample (a fault upstream): hold the last measurement
        const msg::Truth& t = truth_.get();
        const auto m = model_.measure(ctx.k, ctx.t_s, Group::truth(t));
        typename Group::Sample& o = out_.value();
        Group::write(m, o);
        if constexpr (kAligns) {
            if (!aligned_) {  // the alignment ends at the first step (t0) and is published with every sample
                Group::align(align_errors_, t, m, align_stream_, o);
                aligned_ = true;
            }
        }
    }

private:
    static constexpr bool kAligns = requires { &Group::align; };

    framework::Input<msg::Truth> truth_{*this, topics::kTruth};
    framework::Output<typename Group::Sample> out_{*this, Group::kTopic};
    typename Group::Model model_;
    AlignmentErrors align_errors_;
    rnd::Stream align_stream_;
    bool aligned_{false};
};

}  // namespace gdnav::sensors
