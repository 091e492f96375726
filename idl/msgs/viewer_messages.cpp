// The message operations of the viewer channels' types (msgs/viewer_messages.hpp), on the generated type support.
#include "foxglove_schemasPubSubTypes.h"
#include "gdnav_viewerPubSubTypes.h"
#include "msgs/message_ops_impl.hpp"
#include "msgs/viewer_messages.hpp"

GDNAV_DECLARE_MESSAGE(foxglove::LocationFix, foxglove::LocationFixPubSubType)
GDNAV_DECLARE_MESSAGE(foxglove::FrameTransform, foxglove::FrameTransformPubSubType)
GDNAV_DECLARE_MESSAGE(foxglove::PoseInFrame, foxglove::PoseInFramePubSubType)
GDNAV_DECLARE_MESSAGE(gdnav::viewer::NavErrors, gdnav::viewer::NavErrorsPubSubType)
