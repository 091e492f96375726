// The message operations of every gdnav topic type (msgs/message_ops.hpp), on the generated type support.
#include "gdnavPubSubTypes.h"
#include "msgs/message_ops_impl.hpp"
#include "msgs/messages.hpp"

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
