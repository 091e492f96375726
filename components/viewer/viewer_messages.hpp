#pragma once
// The generated C++ types of the viewer channels (idl/foxglove/foxglove_schemas.idl, idl/gdnav_viewer.idl; fastddsgen
// at build time) made known to the type-erased message operations, so that they are serialised exactly like the
// raw topics (runtime::message_ops<T>().serialize: CDR with its encapsulation header, padding zeroed).
#include "foxglove_schemasPubSubTypes.h"
#include "gdnav_viewerPubSubTypes.h"
#include "runtime/message_traits.hpp"

GDNAV_DECLARE_MESSAGE(foxglove::LocationFix, foxglove::LocationFixPubSubType)
GDNAV_DECLARE_MESSAGE(foxglove::FrameTransform, foxglove::FrameTransformPubSubType)
GDNAV_DECLARE_MESSAGE(foxglove::PoseInFrame, foxglove::PoseInFramePubSubType)
GDNAV_DECLARE_MESSAGE(gdnav::viewer::NavErrors, gdnav::viewer::NavErrorsPubSubType)
