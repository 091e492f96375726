#include "framework/lockstep.hpp"

#include <unistd.h>

namespace gdnav::framework {

std::string host_identity() {
    char buf[256] = {};
    gethostname(buf, sizeof(buf) - 1);
    return std::string(buf) + ":" + std::to_string(getpid());
}

}  // namespace gdnav::framework
