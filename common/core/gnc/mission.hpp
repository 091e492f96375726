#pragma once
// A mission: the ordered list of guidance operations of one flight (docs/guidance-control.md, "Guidance").
//
// Each Operation sets a mode and an SI target for each of the four control channels (gnc::ChannelTargets) and a
// Trigger that ends it. The mission ends when the last operation's trigger fires or when t >= t_end_s.
//
// Triggers (all evaluated at 100 Hz on the navigation estimate by guidance, its model's trigger.hpp):
//   time               t >= value [s]                       (absolute simulated time)
//   elapsed            t - t_start >= value [s]             (time since the operation started)
//   bearing            estimated ground bearing chi crosses value [rad]   (wrapped, within +-90 deg)
//   heading            estimated body heading psi crosses value [rad]     (wrapped, within +-90 deg)
//   pressure_altitude  estimated Hp crosses value [m]
//   altitude           estimated h crosses value [m]
//   path_angle         estimated ground path angle gamma (from v_n) crosses value [rad]
//   airspeed           estimated airspeed crosses value [m/s]
//   end                never fires: the operation lasts until the end of the mission
//
// MissionBuilder writes the manoeuvres of the paper as operation sequences:
//   turn            bank +-bank until chi crosses (chi_target -+ lead), then hold chi_target   (2 operations)
//   altitude change air-path angle +-gamma until Hp crosses Hp_target, then hold Hp_target      (2 operations)
//   airspeed change new airspeed target (smoothed by control's set-point ramp)                   (1 operation)
// Every operation inherits the channel settings of the previous one except those it changes.
#include <cstdint>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "gnc/modes.hpp"

namespace gdnav::core::gnc {

enum class TriggerKind : std::uint8_t {
    time,
    elapsed,
    bearing,
    heading,
    pressure_altitude,
    altitude,
    path_angle,
    airspeed,
    end
};
std::string_view trigger_name(TriggerKind kind);

struct Trigger {
    TriggerKind kind{TriggerKind::end};
    double value{0.0};  // SI: s, rad, m or m/s according to kind (unused for `end`)

    static Trigger time(double t_s) { return {TriggerKind::time, t_s}; }
    static Trigger elapsed(double dt_s) { return {TriggerKind::elapsed, dt_s}; }
    static Trigger bearing(double chi_rad) { return {TriggerKind::bearing, chi_rad}; }
    static Trigger heading(double psi_rad) { return {TriggerKind::heading, psi_rad}; }
    static Trigger pressure_altitude(double hp_m) { return {TriggerKind::pressure_altitude, hp_m}; }
    static Trigger altitude(double h_m) { return {TriggerKind::altitude, h_m}; }
    static Trigger path_angle(double gamma_rad) { return {TriggerKind::path_angle, gamma_rad}; }
    static Trigger airspeed(double tas_mps) { return {TriggerKind::airspeed, tas_mps}; }
    static Trigger end() { return {TriggerKind::end, 0.0}; }
};

struct Operation {
    gnc::ChannelTargets targets;
    Trigger trigger;
};

struct Mission {
    std::string name;
    double t_end_s{0.0};
    std::vector<Operation> operations;
};

// Throws std::invalid_argument when the mission cannot be flown: no operations, t_end_s not positive, a mode that
// is not a valid enumerator, a non-finite target or trigger value, or an elapsed trigger that is not positive.
void validate(const Mission& mission);

// Initial flight condition implied by operation 0 (used to set up the initial trimmed state, docs/physics.md,
// "Trim"): available when
// operation 0 holds an airspeed, a pressure altitude and a ground bearing, as in both scenarios.
struct InitialFlight {
    double airspeed_mps{0.0};
    double pressure_altitude_m{0.0};
    double bearing_rad{0.0};
};
std::optional<InitialFlight> initial_flight(const Mission& mission);

enum class TurnDirection : std::uint8_t { automatic, right, left };
enum class VerticalDirection : std::uint8_t { automatic, climb, descend };

class MissionBuilder {
public:
    // `initial` holds the channel settings of the first operation.
    MissionBuilder(std::string name, double t_end_s, const gnc::ChannelTargets& initial);

    // Change one channel of the current settings (applies to the next appended operation onwards).
    MissionBuilder& set_throttle(gnc::ThrottleMode mode, double target);
    MissionBuilder& set_elevator(gnc::ElevatorMode mode, double target);
    MissionBuilder& set_aileron(gnc::AileronMode mode, double target);
    MissionBuilder& set_rudder(gnc::RudderMode mode, double target);

    // Appends one operation holding the current settings until `until` fires.
    MissionBuilder& hold(const Trigger& until);
    // Appends "bank +-bank_rad until chi crosses wrap(to -+ lead)" (right: to - lead, left: to + lead) and
    // "hold bearing `to` until `then_until`".
    // With TurnDirection::automatic the side is the sign of wrap(to - current bearing target), which needs the
    // aileron channel to hold a bearing. Throws std::invalid_argument if the turn is not larger than the lead or
    // the direction cannot be derived.
    MissionBuilder& turn(double to_bearing_rad, double bank_rad, double lead_rad, const Trigger& then_until,
                         TurnDirection direction = TurnDirection::automatic);
    // Appends "air-path angle +-gamma until Hp crosses `to`" and "hold Hp `to` until `then_until`".
    // Automatic direction needs the elevator channel to hold a pressure altitude different from `to`.
    MissionBuilder& change_altitude(double to_pressure_altitude_m, double path_angle_rad, const Trigger& then_until,
                                    VerticalDirection direction = VerticalDirection::automatic);
    // Appends "airspeed `to` until `until`".
    MissionBuilder& change_airspeed(double to_airspeed_mps, const Trigger& until);

    [[nodiscard]] const gnc::ChannelTargets& current() const { return current_; }
    [[nodiscard]] std::size_t size() const { return mission_.operations.size(); }
    // Validates (see validate()) and returns the mission.
    [[nodiscard]] Mission build() const;

private:
    // Sets one channel of the current settings: the mode and the target of the fields named.
    template <class Mode>
    MissionBuilder& set_channel(Mode gnc::ChannelTargets::*mode_field, double gnc::ChannelTargets::*target_field,
                                Mode mode, double target) {
        current_.*mode_field = mode;
        current_.*target_field = target;
        return *this;
    }

    Mission mission_;
    gnc::ChannelTargets current_;
};

}  // namespace gdnav::core::gnc
namespace gdnav { namespace gnc = core::gnc; }  // the short name (docs/architecture.md, "Namespaces")

// Their names in the guidance model's API (the mission lived there before it became a shared GNC type).
namespace gdnav::guidance {
using gnc::InitialFlight;
using gnc::initial_flight;
using gnc::Mission;
using gnc::MissionBuilder;
using gnc::Operation;
using gnc::Trigger;
using gnc::TriggerKind;
using gnc::trigger_name;
using gnc::TurnDirection;
using gnc::validate;
using gnc::VerticalDirection;
}  // namespace gdnav::guidance
