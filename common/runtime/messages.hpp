#pragma once
// All gdnav topics: generated IDL types (idl/gdnav.idl) and their topic names.
#include "gdnavPubSubTypes.h"
#include "runtime/message_traits.hpp"

GDNAV_DECLARE_MESSAGE(gdnav::msg::Tick, gdnav::msg::TickPubSubType)
GDNAV_DECLARE_MESSAGE(gdnav::msg::StepDone, gdnav::msg::StepDonePubSubType)
GDNAV_DECLARE_MESSAGE(gdnav::msg::RunControl, gdnav::msg::RunControlPubSubType)
GDNAV_DECLARE_MESSAGE(gdnav::msg::ComponentStatus, gdnav::msg::ComponentStatusPubSubType)
GDNAV_DECLARE_MESSAGE(gdnav::msg::FaultRequest, gdnav::msg::FaultRequestPubSubType)
GDNAV_DECLARE_MESSAGE(gdnav::msg::Truth, gdnav::msg::TruthPubSubType)
GDNAV_DECLARE_MESSAGE(gdnav::msg::ImuSample, gdnav::msg::ImuSamplePubSubType)
GDNAV_DECLARE_MESSAGE(gdnav::msg::MagSample, gdnav::msg::MagSamplePubSubType)
GDNAV_DECLARE_MESSAGE(gdnav::msg::AirSample, gdnav::msg::AirSamplePubSubType)
GDNAV_DECLARE_MESSAGE(gdnav::msg::AtmSample, gdnav::msg::AtmSamplePubSubType)
GDNAV_DECLARE_MESSAGE(gdnav::msg::GnssSample, gdnav::msg::GnssSamplePubSubType)
GDNAV_DECLARE_MESSAGE(gdnav::msg::AirDataEstimate, gdnav::msg::AirDataEstimatePubSubType)
GDNAV_DECLARE_MESSAGE(gdnav::msg::AttitudeEstimate, gdnav::msg::AttitudeEstimatePubSubType)
GDNAV_DECLARE_MESSAGE(gdnav::msg::PositionEstimate, gdnav::msg::PositionEstimatePubSubType)
GDNAV_DECLARE_MESSAGE(gdnav::msg::GuidanceTargets, gdnav::msg::GuidanceTargetsPubSubType)
GDNAV_DECLARE_MESSAGE(gdnav::msg::ControlCommands, gdnav::msg::ControlCommandsPubSubType)

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
