#pragma once
// The navigation estimates guidance and control close on: three lockstep inputs (AirDataEstimate,
// AttitudeEstimate, PositionEstimate of step k) and their conversion to the plain structs of the GNC models
// (gnc::ControlEstimates for control, guidance::NavState for guidance). Shared by both component wrappers.
#include "gnc/control_estimates.hpp"
#include "gnc/nav_state.hpp"
#include "framework/component.hpp"
#include "msgs/messages.hpp"
#include "framework/msg_eigen.hpp"

namespace gdnav::guidance {

struct EstimateInputs {
    explicit EstimateInputs(framework::Component& owner)
        : air(owner, topics::kAirData), att(owner, topics::kAttitude), pos(owner, topics::kPosition) {}

    [[nodiscard]] bool available() const { return air.available() && att.available() && pos.available(); }
    [[nodiscard]] math::Quat q_nb() const { return framework::to_quat(att.get().q_nb()); }
    [[nodiscard]] math::Vec3 v_n() const { return framework::to_vec3(pos.get().v_n_mps()); }
    [[nodiscard]] NavState nav_state() const {
        return make_nav_state(air.get().tas_mps(), air.get().Hp_m(), pos.get().h_m(), v_n(), q_nb());
    }
    [[nodiscard]] gnc::ControlEstimates control_estimates() const {
        gnc::ControlEstimates e;
        e.airspeed_mps = air.get().tas_mps();
        e.aoa_rad = air.get().aoa_rad();
        e.aos_rad = air.get().aos_rad();
        e.q_nb = q_nb();
        e.v_n_mps = v_n();
        e.pressure_altitude_m = air.get().Hp_m();
        e.altitude_m = pos.get().h_m();
        return e;
    }

    framework::Input<msg::AirDataEstimate> air;
    framework::Input<msg::AttitudeEstimate> att;
    framework::Input<msg::PositionEstimate> pos;
};

}  // namespace gdnav::guidance
