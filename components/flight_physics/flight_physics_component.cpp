#include "flight_physics_component.hpp"

#include <optional>

#include "flight_physics/model/flight_physics.hpp"
#include "gnc/mission_yaml.hpp"
#include "msgs/messages.hpp"
#include "framework/msg_eigen.hpp"
#include "framework/run_config.hpp"

namespace gdnav::physics {

using config::Config;
using config::Range;

namespace {

using framework::to_array;

earth::EarthTruthParams parse_earth(const Config& c) {
    earth::EarthTruthParams e;
    e.dg_mps2 = c.get_double("dg_mps2", {-0.01, 0.01});
    e.tilt_rad = c.get_angle_deg("tilt_deg", {-1.0, 1.0});
    e.tilt_axis_bearing_rad = c.get_angle_deg("tilt_axis_bearing_deg", {-360.0, 360.0});
    e.mag_dev_n_nT = c.get_vec3("mag_dev_n_nT", {-5000.0, 5000.0});
    return e;
}

class FlightPhysicsComponent final : public framework::Component {
public:
    using Component::Component;

    void configure(const Config& cfg, const framework::RunInfo& run, rnd::Stream& stream) override {
        const auto dir = framework::config_dir();
        const auto aircraft_file = cfg.get_file("aircraft", "aircraft/mugin.yaml", dir);
        const AircraftModel aircraft = AircraftModel::load(aircraft_file);
        EnvironmentParams env;
        env.magnetic = earth::MagneticModel::load(cfg.get_file("magnetic_model", "earth/magnetic_wisconsin.yaml", dir));
        if (auto t = cfg.optional_child("turbulence")) {
            env.turbulence = TurbulenceParams::from_config(*t);
            t->finish();
        }
        const std::string draw = cfg.get_choice("draw", "none", {"none", "scenario1", "scenario2"});
        rnd::Stream draws = stream.child("environment");
        if (auto w = cfg.optional_child("wind"))
            env.wind = config::read_number_keys(*w, kWindRampKeys);
        else if (draw != "none")
            env.wind = draw_wind_scenario(draws, draw == "scenario1");
        if (auto o = cfg.optional_child("offsets"))
            env.offsets = config::read_number_keys(*o, atm::kOffsetsRampKeys);
        else if (draw != "none")
            env.offsets = atm::draw_offsets_scenario(draws, draw == "scenario1");
        if (auto e = cfg.optional_child("earth_truth"))
            env.earth = parse_earth(*e);
        else if (draw != "none")
            env.earth = earth::draw_earth_truth(draws);

        const Config init = cfg.child("initial");
        const double lat = init.get_angle_deg("lat_deg", {-80.0, 80.0});
        const double lon = init.get_angle_deg("lon_deg", {-360.0, 360.0});
        const double mass = init.get_double("mass_kg", Range{1.0e-3, 1.0e6});  // as the aircraft file's masses
        double tas = 0.0, Hp = 0.0, bearing = 0.0;
        if (init.has("mission")) {
            const auto m = guidance::load_mission(init.get_file("mission", dir));
            const auto f = guidance::initial_flight(m);
            if (!f) init.fail("mission", "the mission's first operation does not hold airspeed, Hp and bearing");
            tas = f->airspeed_mps;
            Hp = f->pressure_altitude_m;
            bearing = f->bearing_rad;
        } else {
            tas = init.get_double("tas_mps", {15.0, 45.0});
            Hp = init.get_double("Hp_m", {0.0, 8000.0});
            bearing = init.get_angle_deg("bearing_deg", {-360.0, 360.0});
        }
        try {
            fp_.emplace(aircraft, env, stream.child("turbulence"));
            fp_->initialize_trimmed(lat, lon, Hp, tas, bearing, mass, run.t0_s);
        } catch (const std::exception& e) {
            // Names the aircraft file too: a valid-looking aircraft that cannot fly is a likely cause.
            cfg.fail("initial", "cannot start the flight (aircraft " + aircraft_file.string() + "): " + e.what());
        }
        u_ = fp_->trim().controls;
    }

    void step(const framework::StepContext& ctx) override {
        if (ctx.k > 0) {
            if (u_in_.available()) {
                const auto& c = u_in_.get();
                u_ = Controls{c.throttle(), c.elevator_rad(), c.aileron_rad(), c.rudder_rad()};
            }
            fp_->advance(u_, ctx.dt_s);
        }
        fill(fp_->truth());
    }

private:
    void fill(const TruthSample& s) {
        auto& t = out_.value();
        t.lon_rad(s.lon_rad);
        t.lat_rad(s.lat_rad);
        t.h_m(s.h_m);
        t.v_n_mps() = to_array(s.v_n_mps);
        t.q_nb(to_array(s.q_nb));
        t.euler_rad({s.euler.yaw_rad, s.euler.pitch_rad, s.euler.bank_rad});
        t.w_ib_b_rps() = to_array(s.w_ib_b_rps);
        t.w_nb_b_rps() = to_array(s.w_nb_b_rps);
        t.dw_ib_b_rps2() = to_array(s.dw_ib_b_rps2);
        t.f_ib_b_mps2() = to_array(s.f_ib_b_mps2);
        t.tas_mps(s.tas_mps);
        t.aoa_rad(s.aoa_rad);
        t.aos_rad(s.aos_rad);
        t.wind_n_mps() = to_array(s.wind_n_mps);
        t.turb_b_mps() = to_array(s.turb_b_mps);
        t.dT_K(s.dT_K);
        t.dp_Pa(s.dp_Pa);
        t.Hp_m(s.Hp_m);
        t.H_m(s.H_m);
        t.p_Pa(s.p_Pa);
        t.T_K(s.T_K);
        t.rho_kgpm3(s.rho_kgpm3);
        t.g_n_mps2() = to_array(s.g_n_mps2);
        t.g_model_n_mps2() = to_array(s.g_model_n_mps2);
        t.b_n_nT() = to_array(s.b_n_nT);
        t.b_model_n_nT() = to_array(s.b_model_n_nT);
        t.mass_kg(s.mass_kg);
        t.controls({s.controls.throttle, s.controls.elevator_rad, s.controls.aileron_rad, s.controls.rudder_rad});
    }

    framework::Input<msg::ControlCommands> u_in_{*this, topics::kControls, framework::Lag::Previous};
    framework::Output<msg::Truth> out_{*this, topics::kTruth};
    std::optional<FlightPhysics> fp_;
    Controls u_{};
};

}  // namespace

void register_flight_physics(framework::ComponentRegistry& reg) {
    reg.add("flight_physics", "Mugin equations of motion, wind, turbulence, atmosphere: ControlCommands -> Truth",
            framework::make_factory<FlightPhysicsComponent>());
}

}  // namespace gdnav::physics
