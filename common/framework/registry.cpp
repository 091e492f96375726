#include "framework/registry.hpp"

#include <stdexcept>

namespace gdnav::framework {

void ComponentRegistry::add(const std::string& type, std::string description, Factory f) {
    entries_[type] = Entry{std::move(description), std::move(f)};
}

std::unique_ptr<Component> ComponentRegistry::create(const std::string& type, const std::string& instance) const {
    auto it = entries_.find(type);
    if (it == entries_.end()) throw std::runtime_error("unknown component type '" + type + "'");
    return it->second.factory(instance);
}

std::vector<std::string> ComponentRegistry::types() const {
    std::vector<std::string> out;
    for (const auto& [k, v] : entries_) out.push_back(k);
    return out;
}

const std::string& ComponentRegistry::description(const std::string& type) const {
    return entries_.at(type).description;
}

}  // namespace gdnav::framework
