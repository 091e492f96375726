#include "dds/host/host_pulse.hpp"

#include <chrono>

#include "dds/process/process_priority.hpp"

namespace gdnav::dds::host {

Pulse::Pulse() : thread_(&Pulse::loop, this) {}

Pulse::~Pulse() { stop(); }

void Pulse::attach(eprosima::fastdds::dds::DataWriter* writer) {
    const std::lock_guard<std::mutex> lock(mtx_);
    writer_ = writer;
}

void Pulse::loop() {
    const auto period = std::chrono::duration<double>(framework::kHeartbeatPeriodS);
    std::unique_lock<std::mutex> lock(mtx_);
    tid_ = current_tid();
    cv_.notify_all();
    while (!stop_) {
        cv_.wait_for(lock, period);
        if (stop_) break;
        // Only when the main loop is late: while it runs, its own heartbeats carry the current step.
        const double now = framework::steady_now_s();
        if (beat_.empty() || now - sent_s_ < 1.5 * framework::kHeartbeatPeriodS) continue;
        for (msg::ComponentStatus& s : beat_) writer_->write(&s);
        sent_s_ = now;
    }
}

int Pulse::tid() {
    std::unique_lock<std::mutex> lock(mtx_);
    cv_.wait(lock, [this] { return tid_ != 0 || stop_; });
    return tid_;
}

void Pulse::stop() {
    {
        const std::lock_guard<std::mutex> lock(mtx_);
        stop_ = true;
    }
    cv_.notify_all();
    if (thread_.joinable()) thread_.join();
}

}  // namespace gdnav::dds::host
