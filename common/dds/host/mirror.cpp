#include "dds/host/mirror.hpp"

#include <algorithm>

namespace gdnav::dds {

std::string mirror_topic(const std::string& topic) {
    return topic + "/every_" + std::to_string(kMirrorStride) + "_steps";
}

bool may_read_mirror(std::uint64_t stride, bool secure) {
    return !secure && stride != 0 && stride % kMirrorStride == 0;
}

bool reads_mirror(std::uint64_t stride, bool secure, const std::vector<std::string>& producers,
                  const std::function<bool(const std::string&)>& writes_mirror) {
    if (!may_read_mirror(stride, secure) || producers.empty()) return false;
    return std::all_of(producers.begin(), producers.end(), writes_mirror);
}

}  // namespace gdnav::dds
