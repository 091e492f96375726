#include "sensor_components.hpp"

#include "msgs/messages.hpp"
#include "framework/msg_eigen.hpp"
#include "framework/run_config.hpp"
#include "sensors/model/air_data.hpp"
#include "sensors/model/alignment.hpp"
#include "sensors/model/gnss.hpp"
#include "sensors/model/inertial.hpp"
#include "sensors/model/magnetic.hpp"
#include "sensors/model/suite.hpp"

namespace gdnav::sensors {

using runtime::Input;
using runtime::Output;
namespace topics = gdnav::topics;

namespace {

using runtime::to_array;
using runtime::to_vec3;

// Loads the suite named in the component section and applies the run's timing and the section's overrides.
SensorSuiteParams load_suite(const config::Config& cfg, const runtime::RunInfo& run) {
    const auto file = cfg.get_file("suite", "sensors/suite.yaml", runtime::config_dir());
    SensorSuiteParams s = load_sensor_suite(file);
    s.inertial.dt_s = run.dt_s;
    s.mag.dt_s = run.dt_s;
    s.gnss.dt_s = run.dt_s;
    s.gnss.t0_s = run.t0_s;
    return s;
}

// Grade override: re-reads one group's grade file from the suite's folder.
template <class Grade, class Parse>
void override_grade(const config::Config& cfg, const char* key, const char* group, Grade& grade, std::string& name,
                    Parse parse) {
    if (!cfg.has(key)) return;
    const auto dir = cfg.get_file("suite", "sensors/suite.yaml", runtime::config_dir()).parent_path();
    grade = parse(load_grade(cfg, key, dir, group, name));
}

class InertialComponent final : public runtime::Component {
public:
    using Component::Component;
    void configure(const config::Config& cfg, const runtime::RunInfo& run, rnd::Stream& stream) override {
        SensorSuiteParams s = load_suite(cfg, run);
        override_grade(cfg, "gyr_grade", "gyroscopes", s.inertial.gyr, s.gyr_grade, parse_gyro_grade);
        override_grade(cfg, "acc_grade", "accelerometers", s.inertial.acc, s.acc_grade, parse_acc_grade);
        // Same range as the suite's key (the soft pull zone needs N >= 40).
        s.inertial.bias_drift_band = cfg.get_double("bias_drift_band", s.inertial.bias_drift_band, {40.0, 1.0e9});
        model_.configure(s.inertial, stream);
        align_errors_ = s.alignment;
        align_stream_ = stream.child("alignment");
        aligned_ = false;
    }
    void step(const runtime::StepContext& ctx) override {
        if (!truth_.available()) return;  // no truth sample (a fault upstream): hold the last measurement
        const auto& t = truth_.get();
        InertialTruth in{to_vec3(t.f_ib_b_mps2()), to_vec3(t.w_ib_b_rps()), to_vec3(t.dw_ib_b_rps2()), t.mass_kg()};
        const ImuMeasurement m = model_.measure(ctx.k, ctx.t_s, in);
        msg::ImuSample& o = out_.value();
        o.f_b_mps2() = to_array(m.f_b_mps2);
        o.w_b_rps() = to_array(m.w_b_rps);
        if (!aligned_) {  // the fine alignment ends at the first step (t0) and is published with every sample
            const ImuAlignment a =
                align_imu(align_errors_, runtime::to_quat(t.q_nb()), m.e_gyr_rps, m.e_acc_mps2, align_stream_);
            o.align_q_nb() = runtime::to_array(a.q_nb);
            o.align_att_sigma_rad(a.att_sigma_rad);
            o.align_gyr_err_rps() = to_array(a.gyr_err_rps);
            o.align_gyr_err_sigma_rps() = to_array(a.gyr_err_sigma_rps);
            o.align_acc_err_mps2() = to_array(a.acc_err_mps2);
            o.align_acc_err_sigma_mps2() = to_array(a.acc_err_sigma_mps2);
            aligned_ = true;
        }
    }

private:
    Input<msg::Truth> truth_{*this, topics::kTruth};
    Output<msg::ImuSample> out_{*this, topics::kImu};
    InertialSensors model_;
    AlignmentErrors align_errors_;
    rnd::Stream align_stream_;
    bool aligned_{false};
};

class MagneticComponent final : public runtime::Component {
public:
    using Component::Component;
    void configure(const config::Config& cfg, const runtime::RunInfo& run, rnd::Stream& stream) override {
        SensorSuiteParams s = load_suite(cfg, run);
        override_grade(cfg, "grade", "magnetometers", s.mag.grade, s.mag_grade, parse_mag_grade);
        model_.configure(s.mag, stream);
        align_errors_ = s.alignment;
        align_stream_ = stream.child("alignment");
        aligned_ = false;
    }
    void step(const runtime::StepContext& ctx) override {
        if (!truth_.available()) return;  // no truth sample (a fault upstream): hold the last measurement
        const auto& t = truth_.get();
        MagTruth in{runtime::to_quat(t.q_nb()), to_vec3(t.b_n_nT())};
        const MagMeasurement m = model_.measure(ctx.k, ctx.t_s, in);
        msg::MagSample& o = out_.value();
        o.b_b_nT() = to_array(m.b_b_nT);
        if (!aligned_) {  // calibration and magnetic survey at t0, published with every sample
            const MagAlignment a =
                align_mag(align_errors_, m.e_mag_nT, to_vec3(t.b_model_n_nT()) - to_vec3(t.b_n_nT()), align_stream_);
            o.align_mag_err_nT() = to_array(a.mag_err_nT);
            o.align_mag_err_sigma_nT() = to_array(a.mag_err_sigma_nT);
            o.align_b_dev_n_nT() = to_array(a.b_dev_n_nT);
            o.align_b_dev_sigma_nT() = to_array(a.b_dev_sigma_nT);
            aligned_ = true;
        }
    }

private:
    Input<msg::Truth> truth_{*this, topics::kTruth};
    Output<msg::MagSample> out_{*this, topics::kMag};
    Magnetometers model_;
    AlignmentErrors align_errors_;
    rnd::Stream align_stream_;
    bool aligned_{false};
};

class AirComponent final : public runtime::Component {
public:
    using Component::Component;
    void configure(const config::Config& cfg, const runtime::RunInfo& run, rnd::Stream& stream) override {
        SensorSuiteParams s = load_suite(cfg, run);
        override_grade(cfg, "grade", "air_data", s.air.grade, s.air_grade, parse_air_grade);
        model_.configure(s.air, stream);
    }
    void step(const runtime::StepContext& ctx) override {
        if (!truth_.available()) return;  // no truth sample (a fault upstream): hold the last measurement
        const auto& t = truth_.get();
        const AirMeasurement m = model_.measure(ctx.k, ctx.t_s, {t.tas_mps(), t.aoa_rad(), t.aos_rad()});
        out_.value().tas_mps(m.tas_mps);
        out_.value().aoa_rad(m.aoa_rad);
        out_.value().aos_rad(m.aos_rad);
    }

private:
    Input<msg::Truth> truth_{*this, topics::kTruth};
    Output<msg::AirSample> out_{*this, topics::kAir};
    AirDataSensors model_;
};

class AtmosphericComponent final : public runtime::Component {
public:
    using Component::Component;
    void configure(const config::Config& cfg, const runtime::RunInfo& run, rnd::Stream& stream) override {
        SensorSuiteParams s = load_suite(cfg, run);
        override_grade(cfg, "grade", "atmospheric", s.atm.grade, s.atm_grade, parse_atm_grade);
        model_.configure(s.atm, stream);
    }
    void step(const runtime::StepContext& ctx) override {
        if (!truth_.available()) return;  // no truth sample (a fault upstream): hold the last measurement
        const auto& t = truth_.get();
        const AtmMeasurement m = model_.measure(ctx.k, ctx.t_s, {t.p_Pa(), t.T_K()});
        out_.value().p_Pa(m.p_Pa);
        out_.value().T_K(m.T_K);
    }

private:
    Input<msg::Truth> truth_{*this, topics::kTruth};
    Output<msg::AtmSample> out_{*this, topics::kAtm};
    AtmosphericSensors model_;
};

class GnssComponent final : public runtime::Component {
public:
    using Component::Component;
    void configure(const config::Config& cfg, const runtime::RunInfo& run, rnd::Stream& stream) override {
        SensorSuiteParams s = load_suite(cfg, run);
        override_grade(cfg, "grade", "gnss", s.gnss.grade, s.gnss_grade, parse_gnss_grade);
        if (cfg.has("loss_time_s")) s.gnss.loss_time_s = cfg.get_double("loss_time_s", {-1e6, 1e7});
        if (cfg.get_bool("never_lost", false)) s.gnss.loss_time_s.reset();
        model_.configure(s.gnss, stream);
    }
    void step(const runtime::StepContext& ctx) override {
        if (!truth_.available()) return;  // no truth sample (a fault upstream): hold the last measurement
        const auto& t = truth_.get();
        const GnssMeasurement m =
            model_.measure(ctx.k, ctx.t_s, {t.lon_rad(), t.lat_rad(), t.h_m(), to_vec3(t.v_n_mps())});
        auto& o = out_.value();
        o.fix_valid(m.fix_valid);
        o.lon_rad(m.lon_rad);
        o.lat_rad(m.lat_rad);
        o.h_m(m.h_m);
        o.v_n_mps() = to_array(m.v_n_mps);
    }

private:
    Input<msg::Truth> truth_{*this, topics::kTruth};
    Output<msg::GnssSample> out_{*this, topics::kGnss};
    GnssReceiver model_;
};


}  // namespace

void register_sensor_components(runtime::ComponentRegistry& reg) {
    reg.add("sensors_inertial", "gyroscopes + accelerometers: Truth -> ImuSample", runtime::make_factory<InertialComponent>());
    reg.add("sensors_magnetic", "magnetometers: Truth -> MagSample", runtime::make_factory<MagneticComponent>());
    reg.add("sensors_air", "Pitot TAS + AOA/AOS vanes: Truth -> AirSample", runtime::make_factory<AirComponent>());
    reg.add("sensors_atmospheric", "barometer + thermometer: Truth -> AtmSample", runtime::make_factory<AtmosphericComponent>());
    reg.add("sensors_gnss", "GNSS receiver, 1 Hz fixes until t_GNSS: Truth -> GnssSample", runtime::make_factory<GnssComponent>());
}

}  // namespace gdnav::sensors
