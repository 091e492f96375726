// gdnav: the command-line program (build/bin/gdnav).
#include "cli.hpp"
#include "register_components.hpp"

int main(int argc, char** argv) {
    gdnav::framework::ComponentRegistry reg;
    gdnav::cli::register_all_components(reg);
    return gdnav::cli::cli_main(argc, argv, reg, "gdnav");
}
