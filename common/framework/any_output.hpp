#pragma once
// Ports declared by topic name (gdnav::client's input_any/output_any, Python members): the topic's message
// operations, and an output whose message type is chosen at run time.
#include <string>

#include "framework/compat.hpp"
#include "framework/component.hpp"

namespace gdnav::framework {

// The message operations of a registered topic (framework/topic_types.hpp), or std::invalid_argument naming the
// known topics.
const msg::MessageOps& require_topic(const std::string& topic);

class AnyOutput final : public OutputBase {
public:
    AnyOutput(Component& owner, std::string topic, const msg::MessageOps& ops)
        : OutputBase(owner, std::move(topic), ops), value_(ops.create()) {}
    ~AnyOutput() override { ops().destroy(value_); }
    AnyOutput(const AnyOutput&) = delete;
    AnyOutput& operator=(const AnyOutput&) = delete;
    [[nodiscard]] void* data() override { return value_; }

private:
    void* value_;
};

}  // namespace gdnav::framework
