#pragma once
// All gdnav topics: generated IDL types (idl/gdnav.idl) and their topic names. Their message operations are defined
// in msgs/messages.cpp (the one place that includes their DDS type support).
#include "gdnav.h"
#include "msgs/message_ops.hpp"


namespace gdnav::topics {
// Control plane (runtime only).
inline constexpr const char* kTick = "gdnav/Tick";
inline constexpr const char* kStepDone = "gdnav/StepDone";
inline constexpr const char* kRunControl = "gdnav/RunControl";
inline constexpr const char* kStatus = "gdnav/ComponentStatus";
inline constexpr const char* kFaultRequest = "gdnav/FaultRequest";
// Data plane.
inline constexpr const char* kTruth = "gdnav/Truth";
inline constexpr const char* kImu = "gdnav/ImuSample";
inline constexpr const char* kMag = "gdnav/MagSample";
inline constexpr const char* kAir = "gdnav/AirSample";
inline constexpr const char* kAtm = "gdnav/AtmSample";
inline constexpr const char* kGnss = "gdnav/GnssSample";
inline constexpr const char* kAirData = "gdnav/AirDataEstimate";
inline constexpr const char* kAttitude = "gdnav/AttitudeEstimate";
inline constexpr const char* kPosition = "gdnav/PositionEstimate";
inline constexpr const char* kGuidance = "gdnav/GuidanceTargets";
inline constexpr const char* kControls = "gdnav/ControlCommands";
}  // namespace gdnav::topics
