#include "framework/component.hpp"

namespace gdnav::framework {

PortBase::PortBase(Component& owner, std::string topic, const msg::MessageOps& ops)
    : topic_(std::move(topic)), ops_(&ops) {
    (void)owner;
}

InputBase::InputBase(Component& owner, std::string topic, Lag lag, const msg::MessageOps& ops)
    : PortBase(owner, std::move(topic), ops), lag_(lag) {
    owner.inputs_.push_back(this);
}

OutputBase::OutputBase(Component& owner, std::string topic, const msg::MessageOps& ops)
    : PortBase(owner, std::move(topic), ops) {
    owner.outputs_.push_back(this);
}

}  // namespace gdnav::framework
