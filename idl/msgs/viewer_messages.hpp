#pragma once
// The generated C++ types of the viewer channels (idl/foxglove/foxglove_schemas.idl, idl/gdnav_viewer.idl; fastddsgen
// at build time) made known to the type-erased message operations (defined in msgs/viewer_messages.cpp), so that
// they are serialised exactly like the raw topics (msg::message_ops<T>().serialize: CDR with its encapsulation
// header, padding zeroed).
#include "foxglove_schemas.h"
#include "gdnav_viewer.h"
#include "msgs/message_ops.hpp"
