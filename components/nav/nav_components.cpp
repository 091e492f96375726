#include "nav_components.hpp"

#include "nav_files.hpp"

namespace gdnav::nav {

void register_nav_components(framework::ComponentRegistry& reg) {
    register_nav_air(reg);
    register_nav_att(reg);
    register_nav_pos(reg);
}

}  // namespace gdnav::nav
