#include "gnc/mission.hpp"

#include <cmath>
#include <stdexcept>
#include <utility>

#include "math/rotation.hpp"

namespace gdnav::core::gnc {

namespace {

template <class E>
void check_mode(E mode, std::size_t i, const char* channel) {
    if (!gnc::mode_from_octet<E>(gnc::to_octet(mode)))
        throw std::invalid_argument("mission: operation " + std::to_string(i) + ": invalid " + channel + " mode " +
                                    std::to_string(gnc::to_octet(mode)));
}

void check_finite(double v, std::size_t i, const char* what) {
    if (!std::isfinite(v))
        throw std::invalid_argument("mission: operation " + std::to_string(i) + ": " + what + " is not finite");
}

}  // namespace

std::string_view trigger_name(TriggerKind kind) {
    switch (kind) {
        case TriggerKind::time: return "time";
        case TriggerKind::elapsed: return "elapsed";
        case TriggerKind::bearing: return "bearing";
        case TriggerKind::heading: return "heading";
        case TriggerKind::pressure_altitude: return "pressure_altitude";
        case TriggerKind::altitude: return "altitude";
        case TriggerKind::path_angle: return "path_angle";
        case TriggerKind::airspeed: return "airspeed";
        case TriggerKind::end: return "end";
    }
    return "?";
}

void validate(const Mission& mission) {
    if (mission.operations.empty()) throw std::invalid_argument("mission '" + mission.name + "': no operations");
    if (!std::isfinite(mission.t_end_s) || mission.t_end_s <= 0.0)
        throw std::invalid_argument("mission '" + mission.name + "': t_end_s must be positive");
    for (std::size_t i = 0; i < mission.operations.size(); ++i) {
        const Operation& op = mission.operations[i];
        check_mode(op.targets.throttle_mode, i, "throttle");
        check_mode(op.targets.elevator_mode, i, "elevator");
        check_mode(op.targets.aileron_mode, i, "aileron");
        check_mode(op.targets.rudder_mode, i, "rudder");
        check_finite(op.targets.throttle_target, i, "throttle target");
        check_finite(op.targets.elevator_target, i, "elevator target");
        check_finite(op.targets.aileron_target, i, "aileron target");
        check_finite(op.targets.rudder_target, i, "rudder target");
        check_finite(op.trigger.value, i, "trigger value");
        if (trigger_name(op.trigger.kind) == "?")
            throw std::invalid_argument("mission: operation " + std::to_string(i) + ": invalid trigger kind");
        if (op.trigger.kind == TriggerKind::elapsed && op.trigger.value <= 0.0)
            throw std::invalid_argument("mission: operation " + std::to_string(i) + ": elapsed trigger must be > 0 s");
    }
}

std::optional<InitialFlight> initial_flight(const Mission& mission) {
    if (mission.operations.empty()) return std::nullopt;
    const gnc::ChannelTargets& t = mission.operations.front().targets;
    if (t.throttle_mode != gnc::ThrottleMode::airspeed || t.elevator_mode != gnc::ElevatorMode::pressure_altitude ||
        t.aileron_mode != gnc::AileronMode::bearing)
        return std::nullopt;
    return InitialFlight{t.throttle_target, t.elevator_target, t.aileron_target};
}

MissionBuilder::MissionBuilder(std::string name, double t_end_s, const gnc::ChannelTargets& initial)
    : current_(initial) {
    mission_.name = std::move(name);
    mission_.t_end_s = t_end_s;
}

MissionBuilder& MissionBuilder::set_throttle(gnc::ThrottleMode mode, double target) {
    return set_channel(&gnc::ChannelTargets::throttle_mode, &gnc::ChannelTargets::throttle_target, mode, target);
}

MissionBuilder& MissionBuilder::set_elevator(gnc::ElevatorMode mode, double target) {
    return set_channel(&gnc::ChannelTargets::elevator_mode, &gnc::ChannelTargets::elevator_target, mode, target);
}

MissionBuilder& MissionBuilder::set_aileron(gnc::AileronMode mode, double target) {
    return set_channel(&gnc::ChannelTargets::aileron_mode, &gnc::ChannelTargets::aileron_target, mode, target);
}

MissionBuilder& MissionBuilder::set_rudder(gnc::RudderMode mode, double target) {
    return set_channel(&gnc::ChannelTargets::rudder_mode, &gnc::ChannelTargets::rudder_target, mode, target);
}

MissionBuilder& MissionBuilder::hold(const Trigger& until) {
    mission_.operations.push_back({current_, until});
    return *this;
}

MissionBuilder& MissionBuilder::turn(double to_bearing_rad, double bank_rad, double lead_rad, const Trigger& then_until,
                                     TurnDirection direction) {
    const double to = math::wrap_pi(to_bearing_rad);
    if (!(bank_rad > 0.0) || !(lead_rad >= 0.0))
        throw std::invalid_argument("turn: bank must be positive and lead non-negative (magnitudes)");
    const bool holds_bearing = current_.aileron_mode == gnc::AileronMode::bearing;
    const double change = holds_bearing ? math::wrap_pi(to - current_.aileron_target) : 0.0;
    bool right = true;
    if (direction == TurnDirection::automatic) {
        if (!holds_bearing)
            throw std::invalid_argument("turn: direction must be given when the aileron channel holds no bearing");
        if (change == 0.0) throw std::invalid_argument("turn: target equals the bearing already held");
        right = change > 0.0;
    } else {
        right = direction == TurnDirection::right;
    }
    // Ending the bank `lead` before the target only works if the turn is longer than the lead; otherwise the
    // crossing bearing lies behind the aircraft and the turn would go round a full circle.
    if (holds_bearing) {
        const double angle = right ? math::wrap_2pi(change) : math::wrap_2pi(-change);
        if (!(angle > lead_rad))
            throw std::invalid_argument("turn: the turn angle must exceed the roll-out lead");
    }
    set_aileron(gnc::AileronMode::bank, right ? bank_rad : -bank_rad);
    hold(Trigger::bearing(math::wrap_pi(right ? to - lead_rad : to + lead_rad)));
    set_aileron(gnc::AileronMode::bearing, to);
    return hold(then_until);
}

MissionBuilder& MissionBuilder::change_altitude(double to_pressure_altitude_m, double path_angle_rad,
                                                const Trigger& then_until, VerticalDirection direction) {
    if (!(path_angle_rad > 0.0)) throw std::invalid_argument("altitude change: path angle must be positive (magnitude)");
    const bool holds_hp = current_.elevator_mode == gnc::ElevatorMode::pressure_altitude;
    const double change = holds_hp ? to_pressure_altitude_m - current_.elevator_target : 0.0;
    bool climb = true;
    if (direction == VerticalDirection::automatic) {
        if (!holds_hp)
            throw std::invalid_argument(
                "altitude change: direction must be given when the elevator channel holds no pressure altitude");
        if (change == 0.0) throw std::invalid_argument("altitude change: target equals the pressure altitude held");
        climb = change > 0.0;
    } else {
        climb = direction == VerticalDirection::climb;
        if (holds_hp && (change == 0.0 || (change > 0.0) != climb))
            throw std::invalid_argument("altitude change: direction contradicts the pressure altitude held");
    }
    set_elevator(gnc::ElevatorMode::air_path_angle, climb ? path_angle_rad : -path_angle_rad);
    hold(Trigger::pressure_altitude(to_pressure_altitude_m));
    set_elevator(gnc::ElevatorMode::pressure_altitude, to_pressure_altitude_m);
    return hold(then_until);
}

MissionBuilder& MissionBuilder::change_airspeed(double to_airspeed_mps, const Trigger& until) {
    set_throttle(gnc::ThrottleMode::airspeed, to_airspeed_mps);
    return hold(until);
}

Mission MissionBuilder::build() const {
    validate(mission_);
    return mission_;
}

}  // namespace gdnav::core::gnc
