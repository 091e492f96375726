#include "gnc/mission_yaml.hpp"

#include <optional>
#include <stdexcept>
#include <string>
#include <vector>

#include "math/rotation.hpp"

namespace gdnav::core::gnc {

namespace {

using config::Config;
using config::Range;

// Allowed target ranges (file units). Wide enough for any Mugin mission, narrow enough to catch unit mistakes.
constexpr Range kAirspeed_mps{10.0, 60.0};
constexpr Range kAltitude_m{-500.0, 12000.0};
constexpr Range kPitch_deg{-30.0, 30.0};
constexpr Range kPathAngle_deg{-15.0, 15.0};
constexpr Range kBank_deg{-30.0, 30.0};
constexpr Range kBearing_deg{-180.0, 180.0};
constexpr Range kSideslip_deg{-10.0, 10.0};
constexpr Range kTurnBank_deg{0.1, 30.0};
constexpr Range kTurnLead_deg{0.0, 30.0};
constexpr Range kClimbAngle_deg{0.1, 10.0};
constexpr Range kTime_s{-1.0e4, 1.0e6};
constexpr Range kDuration_s{1.0e-3, 1.0e6};
constexpr double kDefaultLead_deg = 5.0;

template <class E>
std::vector<std::string> names_of() {
    std::vector<std::string> v;
    for (const auto& m : gnc::mode_names<E>()) v.emplace_back(m.name);
    return v;
}

template <class E>
E read_mode(const Config& ch) {
    return *gnc::mode_from_name<E>(ch.get_choice("mode", names_of<E>()));
}

// The target key of each mode of a channel (angles in degrees in the file).
template <class E>
struct ModeTarget {
    E mode;
    const char* key;
    bool degrees;
    Range range;
};

using gnc::AileronMode;
using gnc::ElevatorMode;
constexpr ModeTarget<gnc::ThrottleMode> kThrottleTargets[] = {
    {gnc::ThrottleMode::airspeed, "airspeed_mps", false, kAirspeed_mps}};
constexpr ModeTarget<ElevatorMode> kElevatorTargets[] = {
    {ElevatorMode::pitch, "pitch_deg", true, kPitch_deg},
    {ElevatorMode::pressure_altitude, "pressure_altitude_m", false, kAltitude_m},
    {ElevatorMode::altitude, "altitude_m", false, kAltitude_m},
    {ElevatorMode::air_path_angle, "air_path_angle_deg", true, kPathAngle_deg}};
constexpr ModeTarget<AileronMode> kAileronTargets[] = {
    {AileronMode::bank, "bank_deg", true, kBank_deg},
    {AileronMode::bearing, "bearing_deg", true, kBearing_deg},
    {AileronMode::heading, "heading_deg", true, kBearing_deg},
    {AileronMode::air_bank, "air_bank_deg", true, kBank_deg},
    {AileronMode::air_bearing, "air_bearing_deg", true, kBearing_deg}};
constexpr ModeTarget<gnc::RudderMode> kRudderTargets[] = {
    {gnc::RudderMode::sideslip, "sideslip_deg", true, kSideslip_deg}};

void set(MissionBuilder& b, gnc::ThrottleMode m, double target) { b.set_throttle(m, target); }
void set(MissionBuilder& b, ElevatorMode m, double target) { b.set_elevator(m, target); }
void set(MissionBuilder& b, AileronMode m, double target) { b.set_aileron(m, target); }
void set(MissionBuilder& b, gnc::RudderMode m, double target) { b.set_rudder(m, target); }

// A channel's mode and the target its mode reads.
template <class E, std::size_t N>
void read_channel(const Config& ch, const ModeTarget<E> (&targets)[N], MissionBuilder& b) {
    const E mode = read_mode<E>(ch);
    for (const ModeTarget<E>& t : targets)
        if (t.mode == mode) {
            set(b, mode, t.degrees ? ch.get_angle_deg(t.key, t.range) : ch.get_double(t.key, t.range));
            return;
        }
    throw std::logic_error("mission: a mode without a target key");
}

Trigger read_trigger(const Config& op) {
    const Config u = op.child("until");
    const std::string kind = u.get_choice("trigger", {"time", "elapsed", "bearing", "heading", "pressure_altitude",
                                                      "altitude", "path_angle", "airspeed", "end"});
    if (kind == "time") return Trigger::time(u.get_double("t_s", kTime_s));
    if (kind == "elapsed") return Trigger::elapsed(u.get_double("dt_s", kDuration_s));
    if (kind == "bearing") return Trigger::bearing(u.get_angle_deg("bearing_deg", kBearing_deg));
    if (kind == "heading") return Trigger::heading(u.get_angle_deg("heading_deg", kBearing_deg));
    if (kind == "pressure_altitude") return Trigger::pressure_altitude(u.get_double("pressure_altitude_m", kAltitude_m));
    if (kind == "altitude") return Trigger::altitude(u.get_double("altitude_m", kAltitude_m));
    if (kind == "path_angle") return Trigger::path_angle(u.get_angle_deg("path_angle_deg", kPathAngle_deg));
    if (kind == "airspeed") return Trigger::airspeed(u.get_double("airspeed_mps", kAirspeed_mps));
    return Trigger::end();
}

// Channels of a `hold`: all four are required in the first operation, any subset afterwards.
void read_channels(const Config& op, MissionBuilder& b, bool all_required) {
    auto get = [&](const char* key) { return all_required ? std::optional<Config>(op.child(key)) : op.optional_child(key); };
    if (auto ch = get("throttle")) read_channel(*ch, kThrottleTargets, b);
    if (auto ch = get("elevator")) read_channel(*ch, kElevatorTargets, b);
    if (auto ch = get("aileron")) read_channel(*ch, kAileronTargets, b);
    if (auto ch = get("rudder")) read_channel(*ch, kRudderTargets, b);
}

void read_turn(const Config& op, MissionBuilder& b) {
    const double to = op.get_angle_deg("to_bearing_deg", kBearing_deg);
    const double bank = op.get_angle_deg("bank_deg", kTurnBank_deg);
    const double lead = math::deg2rad(op.get_double("lead_deg", kDefaultLead_deg, kTurnLead_deg));
    const std::string dir = op.get_choice("direction", "auto", {"auto", "right", "left"});
    const Trigger until = read_trigger(op);
    if (dir == "auto" && b.current().aileron_mode != gnc::AileronMode::bearing)
        op.fail("direction", "missing: required (right or left) when the previous operation holds no bearing");
    const TurnDirection d = dir == "right"  ? TurnDirection::right
                            : dir == "left" ? TurnDirection::left
                                            : TurnDirection::automatic;
    try {
        b.turn(to, bank, lead, until, d);
    } catch (const std::invalid_argument& e) {
        op.fail("to_bearing_deg", e.what());
    }
}

void read_altitude_change(const Config& op, MissionBuilder& b) {
    const double to = op.get_double("to_pressure_altitude_m", kAltitude_m);
    const double gamma = op.get_angle_deg("path_angle_deg", kClimbAngle_deg);
    const std::string dir = op.get_choice("direction", "auto", {"auto", "climb", "descend"});
    const Trigger until = read_trigger(op);
    if (dir == "auto" && b.current().elevator_mode != gnc::ElevatorMode::pressure_altitude)
        op.fail("direction",
                "missing: required (climb or descend) when the previous operation holds no pressure altitude");
    const VerticalDirection d = dir == "climb"     ? VerticalDirection::climb
                                : dir == "descend" ? VerticalDirection::descend
                                                   : VerticalDirection::automatic;
    try {
        b.change_altitude(to, gamma, until, d);
    } catch (const std::invalid_argument& e) {
        op.fail("to_pressure_altitude_m", e.what());
    }
}

}  // namespace

Mission parse_mission(const Config& cfg) {
    const std::string name = cfg.get_string("name");
    const double t_end_s = cfg.get_double("t_end_s", Range{1.0e-3, 1.0e6});
    const std::vector<Config> ops = cfg.items("operations");
    if (ops.empty()) cfg.fail("operations", "must hold at least one operation");

    MissionBuilder b(name, t_end_s, gnc::ChannelTargets{});
    for (std::size_t i = 0; i < ops.size(); ++i) {
        const Config& op = ops[i];
        const std::string kind = op.get_choice("op", {"hold", "turn", "altitude_change", "airspeed_change"});
        if (i == 0 && kind != "hold") op.fail("op", "the first operation must be 'hold' and set all four channels");
        if (kind == "hold") {
            read_channels(op, b, i == 0);
            b.hold(read_trigger(op));
        } else if (kind == "turn") {
            read_turn(op, b);
        } else if (kind == "altitude_change") {
            read_altitude_change(op, b);
        } else {
            const double v = op.get_double("to_airspeed_mps", kAirspeed_mps);
            b.change_airspeed(v, read_trigger(op));
        }
    }
    cfg.finish();
    try {
        return b.build();
    } catch (const std::invalid_argument& e) {
        cfg.fail("operations", e.what());
    }
}

Mission load_mission(const std::filesystem::path& file) { return parse_mission(Config::load(file)); }

}  // namespace gdnav::core::gnc
