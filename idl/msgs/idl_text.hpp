#pragma once
// The IDL files as written, compiled into their message libraries (cmake/GdnavIdl.cmake generates
// <base>IdlText.cxx: std::string_view msg::idl_text::<base>()): the schema text that recordings and the viewer's
// channels carry (docs/viewing.md).
#include <string_view>

namespace gdnav::msg::idl_text {
std::string_view gdnav();             // idl/gdnav.idl (gdnav_msgs)
std::string_view foxglove_schemas();  // idl/foxglove/foxglove_schemas.idl (gdnav_viewer_msgs)
std::string_view gdnav_viewer();      // idl/gdnav_viewer.idl (gdnav_viewer_msgs)
}  // namespace gdnav::msg::idl_text
