#pragma once
// Channel modes shared by guidance, control and the IDL topic gdnav::msg::GuidanceTargets.
//
// Guidance sets, for each of the four control channels, a mode (which variable that channel controls) and a
// target for that variable in SI units. Control closes one loop per channel on the navigation estimates:
//
//   channel   mode                 controlled variable            target unit   control structure
//   throttle  airspeed             true airspeed V                m/s           primary PID
//   elevator  pitch                body pitch theta               rad           primary PID
//             pressure_altitude    pressure altitude Hp           m             outer PID -> pitch target
//             altitude             geometric altitude h           m             outer PID -> pitch target
//             air_path_angle       air-path angle gamma_TAS       rad           outer PID -> pitch target
//   aileron   bank                 body bank xi                   rad           primary PID
//             bearing              ground-track bearing chi       rad           outer PID -> bank target
//             heading              body heading psi               rad           outer PID -> bank target
//             air_bank             air-path bank mu_TAS           rad           outer PID -> bank target
//             air_bearing          air-path bearing chi_TAS       rad           outer PID -> bank target
//   rudder    sideslip             angle of sideslip beta         rad           primary PID
//
// On the wire (IDL `octet *_mode`) a mode is its enumerator value. Value 0 is never a valid mode, so a
// zero-initialised sample cannot be mistaken for a command.
#include <array>
#include <cstdint>
#include <optional>
#include <string_view>
#include <type_traits>

namespace gdnav::core::gnc {

enum class ThrottleMode : std::uint8_t { airspeed = 1 };
enum class ElevatorMode : std::uint8_t { pitch = 1, pressure_altitude = 2, altitude = 3, air_path_angle = 4 };
enum class AileronMode : std::uint8_t { bank = 1, bearing = 2, heading = 3, air_bank = 4, air_bearing = 5 };
enum class RudderMode : std::uint8_t { sideslip = 1 };

// One mode and target per channel (targets in SI: m/s, m or rad as listed above).
struct ChannelTargets {
    ThrottleMode throttle_mode{ThrottleMode::airspeed};
    double throttle_target{0.0};
    ElevatorMode elevator_mode{ElevatorMode::pitch};
    double elevator_target{0.0};
    AileronMode aileron_mode{AileronMode::bank};
    double aileron_target{0.0};
    RudderMode rudder_mode{RudderMode::sideslip};
    double rudder_target{0.0};
};

// Name of each mode as written in configuration files and logs.
template <class E>
struct ModeName {
    E mode;
    std::string_view name;
};

inline constexpr std::array<ModeName<ThrottleMode>, 1> kThrottleModeNames{{{ThrottleMode::airspeed, "airspeed"}}};
inline constexpr std::array<ModeName<ElevatorMode>, 4> kElevatorModeNames{{{ElevatorMode::pitch, "pitch"},
                                                                         {ElevatorMode::pressure_altitude, "pressure_altitude"},
                                                                         {ElevatorMode::altitude, "altitude"},
                                                                         {ElevatorMode::air_path_angle, "air_path_angle"}}};
inline constexpr std::array<ModeName<AileronMode>, 5> kAileronModeNames{{{AileronMode::bank, "bank"},
                                                                       {AileronMode::bearing, "bearing"},
                                                                       {AileronMode::heading, "heading"},
                                                                       {AileronMode::air_bank, "air_bank"},
                                                                       {AileronMode::air_bearing, "air_bearing"}}};
inline constexpr std::array<ModeName<RudderMode>, 1> kRudderModeNames{{{RudderMode::sideslip, "sideslip"}}};

template <class E>
constexpr const auto& mode_names() {
    if constexpr (std::is_same_v<E, ThrottleMode>) return kThrottleModeNames;
    else if constexpr (std::is_same_v<E, ElevatorMode>) return kElevatorModeNames;
    else if constexpr (std::is_same_v<E, AileronMode>) return kAileronModeNames;
    else return kRudderModeNames;
}

// "airspeed", "pitch", ... ("?" for a value that is not a mode).
template <class E>
constexpr std::string_view mode_name(E mode) {
    for (const auto& m : mode_names<E>())
        if (m.mode == mode) return m.name;
    return "?";
}

template <class E>
constexpr std::optional<E> mode_from_name(std::string_view name) {
    for (const auto& m : mode_names<E>())
        if (m.name == name) return m.mode;
    return std::nullopt;
}

template <class E>
constexpr std::uint8_t to_octet(E mode) {
    return static_cast<std::uint8_t>(mode);
}

// The mode carried by an IDL octet, or nullopt when the octet is not a valid mode of that channel.
template <class E>
constexpr std::optional<E> mode_from_octet(std::uint8_t octet) {
    for (const auto& m : mode_names<E>())
        if (static_cast<std::uint8_t>(m.mode) == octet) return m.mode;
    return std::nullopt;
}

// True when the elevator / aileron mode is served by an outer (secondary) loop.
constexpr bool has_outer_loop(ElevatorMode m) { return m != ElevatorMode::pitch; }
constexpr bool has_outer_loop(AileronMode m) { return m != AileronMode::bank; }

}  // namespace gdnav::core::gnc
namespace gdnav { namespace gnc = core::gnc; }  // the short name (docs/architecture.md, "Namespaces")
