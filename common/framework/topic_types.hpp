#pragma once
// Topic name -> message type, for components that choose their topics from config (the recorder).
#include <string>
#include <string_view>
#include <vector>

#include "framework/compat.hpp"
#include "msgs/message_ops.hpp"

namespace gdnav::framework {

// `schema_idl`: the text of the IDL file that defines the type (its fully-qualified name is ops.type_name), which
// recordings carry as the channel's schema (MCAP, encoding omgidl; empty: no schema); it must outlive the program.
void register_topic(const std::string& topic, const msg::MessageOps& ops, std::string_view schema_idl = {});
template <class T>
void register_topic(const std::string& topic, std::string_view schema_idl = {}) {
    register_topic(topic, msg::message_ops<T>(), schema_idl);
}
// nullptr when unknown.
const msg::MessageOps* find_topic(const std::string& topic);
// The IDL text registered with the topic (empty when unknown or registered without one).
std::string_view topic_schema_idl(const std::string& topic);
std::vector<std::string> known_topics();
// Registers every gdnav/... data topic of idl/gdnav.idl.
void register_gdnav_topics();

}  // namespace gdnav::framework
