// The message operations of the alignment status type (msgs/alignment_messages.hpp), on the generated type support.
#include "gdnav_alignmentPubSubTypes.h"
#include "msgs/alignment_messages.hpp"
#include "msgs/message_ops_impl.hpp"

GDNAV_DECLARE_MESSAGE(gdnav::msg::NavAlignment, gdnav::msg::NavAlignmentPubSubType)
GDNAV_DECLARE_MESSAGE(gdnav::msg::NavHandover, gdnav::msg::NavHandoverPubSubType)
