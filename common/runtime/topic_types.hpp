#pragma once
// Topic name -> message type, for components that choose their topics from config (the recorder).
#include <string>
#include <vector>

#include "runtime/message_traits.hpp"

namespace gdnav::runtime {

void register_topic(const std::string& topic, const MessageOps& ops);
template <class T>
void register_topic(const std::string& topic) {
    register_topic(topic, message_ops<T>());
}
// nullptr when unknown.
const MessageOps* find_topic(const std::string& topic);
std::vector<std::string> known_topics();
// Registers every gdnav/... data topic of idl/gdnav.idl.
void register_gdnav_topics();

}  // namespace gdnav::runtime
