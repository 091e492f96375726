// gdnav-testchain: the gdnav command line with the test chain components (tests only).
#include "chain_components.hpp"
#include "cli.hpp"
#include "recorder.hpp"

int main(int argc, char** argv) {
    gdnav::framework::ComponentRegistry reg;
    gdnav::recorder::register_recorder(reg);
    gdnav::testchain::register_chain(reg);
    return gdnav::cli::cli_main(argc, argv, reg, "gdnav-testchain");
}
