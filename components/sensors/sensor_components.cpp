#include "sensor_components.hpp"

#include "framework/msg_eigen.hpp"
#include "sensor_group_component.hpp"
#include "sensors/model/air_data.hpp"
#include "sensors/model/gnss.hpp"
#include "sensors/model/inertial.hpp"
#include "sensors/model/magnetic.hpp"

namespace gdnav::sensors {

namespace topics = gdnav::topics;

namespace {

using framework::to_array;
using framework::to_vec3;

struct Inertial {
    using Model = InertialSensors;
    using Sample = msg::ImuSample;
    static constexpr const char* kTopic = topics::kImu;
    static InertialParams& params(SensorSuiteParams& s) { return s.inertial; }
    static void apply_overrides(const config::Config& cfg, SensorSuiteParams& s) {
        override_grade(cfg, "gyr_grade", "gyroscopes", s.inertial.gyr, s.gyr_grade, parse_gyro_grade);
        override_grade(cfg, "acc_grade", "accelerometers", s.inertial.acc, s.acc_grade, parse_acc_grade);
        // Same range as the suite's key (the soft pull zone needs N >= 40).
        s.inertial.bias_drift_band = cfg.get_double("bias_drift_band", s.inertial.bias_drift_band, {40.0, 1.0e9});
    }
    static InertialTruth truth(const msg::Truth& t) {
        return {to_vec3(t.f_ib_b_mps2()), to_vec3(t.w_ib_b_rps()), to_vec3(t.dw_ib_b_rps2()), t.mass_kg()};
    }
    static void write(const ImuMeasurement& m, Sample& o) {
        o.f_b_mps2() = to_array(m.f_b_mps2);
        o.w_b_rps() = to_array(m.w_b_rps);
    }
    // The fine alignment, from the true attitude and the sensors' own errors at t0.
    static void align(const AlignmentErrors& e, const msg::Truth& t, const ImuMeasurement& m, rnd::Stream& stream,
                      Sample& o) {
        const ImuAlignment a = align_imu(e, framework::to_quat(t.q_nb()), m.e_gyr_rps, m.e_acc_mps2, stream);
        o.align_q_nb() = framework::to_array(a.q_nb);
        o.align_att_sigma_rad(a.att_sigma_rad);
        o.align_gyr_err_rps() = to_array(a.gyr_err_rps);
        o.align_gyr_err_sigma_rps() = to_array(a.gyr_err_sigma_rps);
        o.align_acc_err_mps2() = to_array(a.acc_err_mps2);
        o.align_acc_err_sigma_mps2() = to_array(a.acc_err_sigma_mps2);
    }
};

struct Magnetic {
    using Model = Magnetometers;
    using Sample = msg::MagSample;
    static constexpr const char* kTopic = topics::kMag;
    static MagParams& params(SensorSuiteParams& s) { return s.mag; }
    static void apply_overrides(const config::Config& cfg, SensorSuiteParams& s) {
        override_grade(cfg, "grade", "magnetometers", s.mag.grade, s.mag_grade, parse_mag_grade);
    }
    static MagTruth truth(const msg::Truth& t) { return {framework::to_quat(t.q_nb()), to_vec3(t.b_n_nT())}; }
    static void write(const MagMeasurement& m, Sample& o) { o.b_b_nT() = to_array(m.b_b_nT); }
    // Calibration and magnetic survey: the sensors' errors and the field's deviation from the model at t0.
    static void align(const AlignmentErrors& e, const msg::Truth& t, const MagMeasurement& m, rnd::Stream& stream,
                      Sample& o) {
        const MagAlignment a = align_mag(e, m.e_mag_nT, to_vec3(t.b_model_n_nT()) - to_vec3(t.b_n_nT()), stream);
        o.align_mag_err_nT() = to_array(a.mag_err_nT);
        o.align_mag_err_sigma_nT() = to_array(a.mag_err_sigma_nT);
        o.align_b_dev_n_nT() = to_array(a.b_dev_n_nT);
        o.align_b_dev_sigma_nT() = to_array(a.b_dev_sigma_nT);
    }
};

struct Air {
    using Model = AirDataSensors;
    using Sample = msg::AirSample;
    static constexpr const char* kTopic = topics::kAir;
    static AirParams& params(SensorSuiteParams& s) { return s.air; }
    static void apply_overrides(const config::Config& cfg, SensorSuiteParams& s) {
        override_grade(cfg, "grade", "air_data", s.air.grade, s.air_grade, parse_air_grade);
    }
    static AirTruth truth(const msg::Truth& t) { return {t.tas_mps(), t.aoa_rad(), t.aos_rad()}; }
    static void write(const AirMeasurement& m, Sample& o) {
        o.tas_mps(m.tas_mps);
        o.aoa_rad(m.aoa_rad);
        o.aos_rad(m.aos_rad);
    }
};

struct Atmospheric {
    using Model = AtmosphericSensors;
    using Sample = msg::AtmSample;
    static constexpr const char* kTopic = topics::kAtm;
    static AtmParams& params(SensorSuiteParams& s) { return s.atm; }
    static void apply_overrides(const config::Config& cfg, SensorSuiteParams& s) {
        override_grade(cfg, "grade", "atmospheric", s.atm.grade, s.atm_grade, parse_atm_grade);
    }
    static AtmTruth truth(const msg::Truth& t) { return {t.p_Pa(), t.T_K()}; }
    static void write(const AtmMeasurement& m, Sample& o) {
        o.p_Pa(m.p_Pa);
        o.T_K(m.T_K);
    }
};

struct Gnss {
    using Model = GnssReceiver;
    using Sample = msg::GnssSample;
    static constexpr const char* kTopic = topics::kGnss;
    static GnssParams& params(SensorSuiteParams& s) { return s.gnss; }
    static void apply_overrides(const config::Config& cfg, SensorSuiteParams& s) {
        override_grade(cfg, "grade", "gnss", s.gnss.grade, s.gnss_grade, parse_gnss_grade);
        if (cfg.has("loss_time_s")) s.gnss.loss_time_s = cfg.get_double("loss_time_s", {-1e6, 1e7});
        if (cfg.get_bool("never_lost", false)) s.gnss.loss_time_s.reset();
    }
    static GnssTruth truth(const msg::Truth& t) {
        return {t.lon_rad(), t.lat_rad(), t.h_m(), to_vec3(t.v_n_mps())};
    }
    static void write(const GnssMeasurement& m, Sample& o) {
        o.fix_valid(m.fix_valid);
        o.lon_rad(m.lon_rad);
        o.lat_rad(m.lat_rad);
        o.h_m(m.h_m);
        o.v_n_mps() = to_array(m.v_n_mps);
    }
};

template <class Group>
framework::ComponentRegistry::Factory factory() {
    return framework::make_factory<SensorGroupComponent<Group>>();
}

}  // namespace

void register_sensor_components(framework::ComponentRegistry& reg) {
    reg.add("sensors_inertial", "gyroscopes + accelerometers: Truth -> ImuSample", factory<Inertial>());
    reg.add("sensors_magnetic", "magnetometers: Truth -> MagSample", factory<Magnetic>());
    reg.add("sensors_air", "Pitot TAS + AOA/AOS vanes: Truth -> AirSample", factory<Air>());
    reg.add("sensors_atmospheric", "barometer + thermometer: Truth -> AtmSample", factory<Atmospheric>());
    reg.add("sensors_gnss", "GNSS receiver, 1 Hz fixes until t_GNSS: Truth -> GnssSample", factory<Gnss>());
}

}  // namespace gdnav::sensors
