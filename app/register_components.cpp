#include "register_components.hpp"

#include "recorder.hpp"

namespace gdnav::app {

void register_all_components(runtime::ComponentRegistry& reg) {
    recorder::register_recorder(reg);
}

}  // namespace gdnav::app
