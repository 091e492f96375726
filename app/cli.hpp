#pragma once
// The gdnav command line (CLI11). Programs register the components they link and call cli_main.
#include "framework/registry.hpp"

namespace gdnav::cli {

int cli_main(int argc, char** argv, const framework::ComponentRegistry& reg, const char* program_name);

}  // namespace gdnav::cli
