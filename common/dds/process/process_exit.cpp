#include "dds/process/process_exit.hpp"

#include <atomic>
#include <cstdio>
#include <cstdlib>

#include <spdlog/spdlog.h>

namespace gdnav::runtime {

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

}  // namespace gdnav::runtime
