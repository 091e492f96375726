// gdnav: the command-line program (build/bin/gdnav).
#include "cli.hpp"
#include "register_components.hpp"

int main(int argc, char** argv) {
    gdnav::runtime::ComponentRegistry reg;
    gdnav::app::register_all_components(reg);
    return gdnav::app::cli_main(argc, argv, reg, "gdnav");
}
