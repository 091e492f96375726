#pragma once
// The members' heartbeats (docs/protocol.md §5, "Heartbeats come from the process, not from the step"): the main
// loop sends them every kHeartbeatPeriodS; a pulse thread repeats the last ones while the main loop is held up (a
// long step, a write that blocks on the disk): a heartbeat says the process is alive, and a member that is alive but
// makes no progress is the clock's stall_timeout_s to judge, not member_timeout_s.
#include <condition_variable>
#include <cstddef>
#include <mutex>
#include <thread>
#include <vector>

#include <fastdds/dds/publisher/DataWriter.hpp>

#include "dds/compat.hpp"
#include "framework/lockstep.hpp"
#include "msgs/messages.hpp"

namespace gdnav::dds::host {

// Neither copied nor moved (its mutex and thread are not): the thread holds `this`.
class Pulse {
public:
    // The pulse thread starts here, before the host lowers its process's CPU priority, which spares it (tid()).
    Pulse();
    ~Pulse();

    // The ComponentStatus writer the heartbeats go on (before the first send()).
    void attach(eprosima::fastdds::dds::DataWriter* writer);

    // Whether the main loop's heartbeats are due at `now`; when they are, the next ones are due a period later.
    bool due(double now) {
        if (now < next_s_) return false;
        next_s_ = now + framework::kHeartbeatPeriodS;
        return true;
    }
    // The next heartbeats are due at once (READY, a fault schedule to acknowledge).
    void hurry() { next_s_ = 0.0; }
    // The main loop's heartbeats at `now`: fill(i, status) fills member i's of n, written at once. They are filled in
    // place: the pulse repeats exactly these samples, and their strings keep their storage.
    template <class Fill>
    void send(double now, std::size_t n, Fill&& fill) {
        const std::lock_guard<std::mutex> lock(mtx_);
        beat_.resize(n);
        for (std::size_t i = 0; i < n; ++i) {
            fill(i, beat_[i]);
            writer_->write(&beat_[i]);
        }
        sent_s_ = now;
    }

    // The pulse thread's id (waits until it has started).
    [[nodiscard]] int tid();
    // Ends the pulse thread: when the main loop ends, before the last statuses and before DDS is torn down.
    void stop();

private:
    void loop();

    eprosima::fastdds::dds::DataWriter* writer_{nullptr};
    double next_s_{0.0};  // when the main loop's next heartbeats are due (main loop only)

    // The heartbeats the main loop sent last, and when (steady seconds); both under mtx_.
    std::mutex mtx_;
    std::condition_variable cv_;
    std::vector<msg::ComponentStatus> beat_;
    double sent_s_{0.0};
    bool stop_{false};
    int tid_{0};
    std::thread thread_;  // last: it starts once the members above are made
};

}  // namespace gdnav::dds::host
