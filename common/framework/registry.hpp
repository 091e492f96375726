#pragma once
// Component factories by type name. Each component library exposes `void register_<lib>(ComponentRegistry&)`;
// a program (gdnav, gdnav-testchain) registers what it links and hands the registry to the CLI.
#include <functional>
#include <map>
#include <memory>
#include <string>
#include <vector>

#include "framework/compat.hpp"
#include "framework/component.hpp"

namespace gdnav::framework {

class ComponentRegistry {
public:
    using Factory = std::function<std::unique_ptr<Component>(const std::string& instance_name)>;
    void add(const std::string& type, std::string description, Factory f);
    [[nodiscard]] bool has(const std::string& type) const { return entries_.count(type) != 0; }
    [[nodiscard]] std::unique_ptr<Component> create(const std::string& type, const std::string& instance) const;
    [[nodiscard]] std::vector<std::string> types() const;
    [[nodiscard]] const std::string& description(const std::string& type) const;

private:
    struct Entry {
        std::string description;
        Factory factory;
    };
    std::map<std::string, Entry> entries_;
};

// Factory of a component class constructed from its instance name.
template <class C>
ComponentRegistry::Factory make_factory() {
    return [](const std::string& name) { return std::make_unique<C>(name); };
}

}  // namespace gdnav::framework
