#include "dds/process/process_exit.hpp"

#include <atomic>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <thread>

#include <spdlog/spdlog.h>

namespace gdnav::dds {

namespace {
std::atomic<bool> g_keep{false};
}  // namespace

void keep_participants_until_exit() { g_keep.store(true); }

bool participants_kept() { return g_keep.load(); }

void exit_keeping_participants(int code) {
    spdlog::apply_all([](const std::shared_ptr<spdlog::logger>& l) { l->flush(); });
    std::fflush(nullptr);
    std::_Exit(code);
}

void bound_teardown(int code, double deadline_s) {
    std::thread([code, deadline_s] {
        std::this_thread::sleep_for(std::chrono::duration<double>(deadline_s));
        spdlog::warn("DDS tear-down still running {:.0f} s after the run's results were written; leaving with exit "
                     "code {}",
                     deadline_s, code);
        exit_keeping_participants(code);
    }).detach();
}

}  // namespace gdnav::dds
