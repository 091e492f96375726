#pragma once
// Lockstep protocol constants and small helpers shared by the clock and the DDS hosts.
//
//   1. Every member publishes ComponentStatus heartbeats (10 Hz wall time) announcing its inputs and outputs.
//   2. When every configured member is present, the clock publishes RunControl CONFIGURE with the member table.
//   3. Each host waits until its readers and writers have matched every peer the table implies, then reports READY.
//   4. The clock publishes Tick(0) once every member is READY and its Tick writer reaches every host.
//   5. A member steps k when every lockstep input of step k (k-1 for Lag::Previous) is in its inbox, publishes its
//      outputs and StepDone(k). The clock sends Tick(k+1) when every live barrier member reported StepDone(k).
//   6. Heartbeats that stop for member_timeout_s declare a member dead: the clock re-sends Tick(k) with the member
//      in dead_mask; consumers stop waiting for its topics. Losing an essential member aborts the run.
//   7. Members that hear neither Tick nor clock heartbeat for member_timeout_s exit non-zero naming the clock.
//      A silence is counted only while the listener itself runs (own_stall_s below).
//   8. After the last step the clock publishes RunControl STOP; everybody finishes and exits 0.
#include <chrono>
#include <cstdint>
#include <string>

#include "framework/compat.hpp"

namespace gdnav::framework {

inline constexpr double kHeartbeatPeriodS = 0.1;
inline constexpr double kWaitSliceS = 0.02;  // longest blocking wait in a loop (signals, heartbeats, timeouts)
inline constexpr std::size_t kInboxRing = 128;  // > window_steps + 2 (a producer can be that far ahead)
inline constexpr const char* kClockName = "clock";
// How long a starting clock listens for another clock on its domain before it takes the domain (several periods
// of the clocks' heartbeats after DDS discovery between two participants of one host; docs/runtime.md).
inline constexpr double kClaimListenS = 1.0;
// The claim goes on while the domain shows other life (a participant discovered, a status of another run's member)
// until kClaimQuietS without it, and at most kClaimLongestS: under load another clock's heartbeat can come after
// kClaimListenS, while its participants are still being discovered (docs/protocol.md §1). A domain where nothing
// else lives pays kClaimListenS only; one where a finished run's members linger pays kClaimLongestS.
inline constexpr double kClaimQuietS = 0.5;
inline constexpr double kClaimLongestS = 3.0;

// Exit codes of runtime processes.
inline constexpr int kExitOk = 0;
inline constexpr int kExitConfig = 2;
inline constexpr int kExitAborted = 3;
inline constexpr int kExitLostClock = 4;
inline constexpr int kExitStartup = 5;
// An output file could not be written (a full disk, a file size limit, an I/O error): docs/runtime.md "Exit codes".
inline constexpr int kExitWriteFailed = 6;
inline constexpr int kExitInterrupted = 130;

// A loop that did not come round for longer than a wait slice plus this margin was not scheduled (a loaded machine,
// a niced observer process): the peers' messages of that time may still wait in its transport, unread, so the
// time is not counted as their silence. The clock and the hosts shift their silence timers by own_stall_s().
inline constexpr double kOwnStallMarginS = 0.25;
inline double own_stall_s(double since_last_loop_s) {
    return since_last_loop_s > kWaitSliceS + kOwnStallMarginS ? since_last_loop_s - kWaitSliceS : 0.0;
}

inline double steady_now_s() {
    return std::chrono::duration<double>(std::chrono::steady_clock::now().time_since_epoch()).count();
}

std::string host_identity();  // hostname:pid

}  // namespace gdnav::framework
