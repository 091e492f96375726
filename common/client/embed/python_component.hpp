#pragma once
// The component `python_member`: an instance of the user's member class, whose step(k, t_s) is the component's step.
#include <cstdint>
#include <memory>
#include <string>
#include <vector>

#include <pybind11/pybind11.h>

#include "client/python/bindings.hpp"
#include "framework/component.hpp"
#include "framework/registry.hpp"
#include "client/python/port.hpp"
#include "client/python/step_call.hpp"

namespace gdnav::client::embed {

using python::Port;
using python::StepCost;
using python::StepView;

class PythonComponent;

// What the class's constructor gets in-process: the member calls of gdnav_client.Member that make sense inside
// gdnav (ports, status, name, run id, step view, step cost). Ports are declared only in the constructor.
class Host {
public:
    explicit Host(PythonComponent& c) : comp_(&c) {}
    std::shared_ptr<Port> input(const std::string& topic, framework::Lag lag);
    std::shared_ptr<Port> output(const std::string& topic);
    void publish_status(const std::string& message);
    [[nodiscard]] const std::string& name() const;
    [[nodiscard]] std::uint64_t run_id() const;
    [[nodiscard]] StepView step_view() const;
    [[nodiscard]] const StepCost& cost() const;
    void close() { comp_ = nullptr; }  // the component is gone

private:
    [[nodiscard]] PythonComponent& comp() const;
    PythonComponent* comp_;
};

class PythonComponent final : public framework::Component {
public:
    PythonComponent(std::string name, const framework::ComponentRegistry& reg);
    ~PythonComponent() override;
    PythonComponent(const PythonComponent&) = delete;
    PythonComponent& operator=(const PythonComponent&) = delete;

    void configure(const config::Config& cfg, const framework::RunInfo& run, rnd::Stream& stream) override;
    void step(const framework::StepContext& ctx) override;
    void finish(bool completed) override;

private:
    friend class Host;
    void instantiate();                        // GIL held
    void check_ports(const std::string& replaces) const;
    // A ConfigError naming `where` (default: the file).
    [[noreturn]] void fail(const std::string& what, const std::string& where = "") const;

    const framework::ComponentRegistry& reg_;
    std::string file_, class_;
    framework::RunInfo run_;
    StepView view_;
    StepCost cost_;
    std::shared_ptr<python::StepState> state_ = std::make_shared<python::StepState>();
    std::vector<std::unique_ptr<framework::InputBase>> inputs_;
    std::vector<std::unique_ptr<framework::OutputBase>> outputs_;
    bool declaring_{false};
    std::shared_ptr<Host> host_;
    pybind11::object module_, obj_, finish_;
    pybind11::function step_;
    std::string module_name_;
};

}  // namespace gdnav::client::embed
