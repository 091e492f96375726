#include "truth_as_estimate.hpp"

#include "msgs/messages.hpp"

namespace gdnav::diagnostics {

namespace {

class TruthAsEstimate final : public framework::Component {
public:
    using Component::Component;
    void configure(const config::Config&, const framework::RunInfo&, rnd::Stream&) override {}
    void step(const framework::StepContext&) override {
        if (!truth_.available()) return;  // hold the last estimates
        const auto& t = truth_.get();
        auto& a = air_.value();
        a.tas_mps(t.tas_mps());
        a.aoa_rad(t.aoa_rad());
        a.aos_rad(t.aos_rad());
        a.dT_K(t.dT_K());
        a.Hp_m(t.Hp_m());
        a.T_K(t.T_K());
        auto& q = att_.value();
        q.q_nb(t.q_nb());
        q.euler_rad(t.euler_rad());
        q.w_nb_b_rps(t.w_nb_b_rps());
        auto& p = pos_.value();
        p.lon_rad(t.lon_rad());
        p.lat_rad(t.lat_rad());
        p.h_m(t.h_m());
        p.v_n_mps(t.v_n_mps());
        p.wind_n_mps(t.wind_n_mps());
        p.Hp_m(t.Hp_m());
        p.dp_Pa(t.dp_Pa());
        p.dT_K(t.dT_K());
        p.gnss_denied(false);
    }

private:
    framework::Input<msg::Truth> truth_{*this, topics::kTruth};
    framework::Output<msg::AirDataEstimate> air_{*this, topics::kAirData};
    framework::Output<msg::AttitudeEstimate> att_{*this, topics::kAttitude};
    framework::Output<msg::PositionEstimate> pos_{*this, topics::kPosition};
};

}  // namespace

void register_diagnostics(framework::ComponentRegistry& reg) {
    reg.add("truth_as_estimate", "diagnostic: Truth republished as the navigation estimate topics",
            framework::make_factory<TruthAsEstimate>());
}

}  // namespace gdnav::diagnostics
