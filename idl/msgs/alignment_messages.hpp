#pragma once
// The in-flight alignment status types (idl/gdnav_alignment.idl) and their topics, made known to the type-erased message
// operations (msgs/alignment_messages.cpp). Not in the list of gdnav data topics (topic_types.hpp): it exists only in
// runs that ask for it.
#include "gdnav_alignment.h"
#include "msgs/message_ops.hpp"

namespace gdnav::topics {
inline constexpr const char* kAlignment = "gdnav/NavAlignment";
inline constexpr const char* kHandover = "gdnav/NavHandover";
}  // namespace gdnav::topics
