#pragma once
// SIGINT/SIGTERM handling for runtime processes: the handler only sets a flag that the loops poll.
#include <atomic>

#include "dds/compat.hpp"

namespace gdnav::dds {

void install_stop_signal_handlers();
bool stop_requested();
int stop_signal();  // the signal that requested the stop (0 if none)

}  // namespace gdnav::dds
