#pragma once
// What only an executor does to a component (the direct executor, a DDS host, an in-process Python member's host,
// a test that steps a component by hand): binding an input to the sample of the step, marking it lost, draining the
// statuses the component published. Kept off the component author's surface (framework/component.hpp), where a
// component only reads its inputs, writes its outputs and publishes statuses.
#include <string>
#include <utility>
#include <vector>

#include "framework/compat.hpp"
#include "framework/component.hpp"

namespace gdnav::framework {

struct ExecutorAccess {
    // The input holds DATA (the sample of the step; nullptr: none this step).
    static void bind(InputBase& in, const void* data) { in.bind(data); }
    // The producer was declared dead (true, the input is never available again unless revived) or was restarted.
    static void set_lost(InputBase& in, bool lost) { in.set_lost(lost); }
    // The statuses the component published since the last drain, in order.
    static std::vector<std::string> take_status(Component& c) { return std::exchange(c.status_, {}); }
    // A status published for the component by its host (an in-process Python member publishes through it).
    static void publish_status(Component& c, std::string message) { c.status_.push_back(std::move(message)); }
};

}  // namespace gdnav::framework
