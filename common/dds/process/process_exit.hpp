#pragma once
// How a gdnav process that took part in a run ends: without deleting its DDS participant.
//
// Deleting a participant announces its leaving to every peer (a DISPOSE of its discovery data). Fast DDS 2.9.1
// aborts a peer that handles such a DISPOSE while the lease timer of the same remote participant fires (an
// assertion in PDP::check_remote_participant_liveliness: the timer callback finds the proxy already cleared; docs/
// runtime.md, "Shutdown"). A run's processes leave together, so the DISPOSEs come in a burst while slower peers
// still write their results. A process that keeps its participants until it ends sends none: its peers drop it
// when its lease expires, on their timer thread alone, where the race cannot happen.
#include "dds/compat.hpp"
namespace gdnav::dds {

// From now on DdsContext's destructor deletes the readers and writers but not the participant; the process must then
// end through exit_keeping_participants (a normal exit would delete it from the factory's static destructor).
void keep_participants_until_exit();
[[nodiscard]] bool participants_kept();

// Flushes the logs and the C streams and ends the process with `code` at once: no static destructor runs, so no
// participant is deleted. Call it only when every result is written and closed (the host and the clock destroyed).
[[noreturn]] void exit_keeping_participants(int code);

// Bounds the tear-down that follows a run whose results are all written: if the process has not ended `deadline_s`
// from now, it leaves through exit_keeping_participants(code), with one warning. Fast DDS 2.9.1 can deadlock while it
// deletes an endpoint matched with a peer whose lease expires at that moment (docs/runtime.md, "Shutdown"), and a
// process that never ends holds its launcher and every run queued behind it.
void bound_teardown(int code, double deadline_s);

}  // namespace gdnav::dds
