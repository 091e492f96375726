#pragma once
// Reads the runtime recorder's per-topic CDR files (<out>/record/<topic>.cdr) back into IDL messages.
#include <cstdint>
#include <filesystem>
#include <fstream>
#include <stdexcept>
#include <vector>

#include "runtime/messages.hpp"

namespace gdnav::testing {

template <class T>
std::vector<T> read_records(const std::filesystem::path& out_dir, const std::string& topic) {
    std::string name;
    for (char c : topic) name += (c == '/') ? std::string("__") : std::string(1, c);
    std::ifstream f(out_dir / "record" / (name + ".cdr"), std::ios::binary);
    if (!f) throw std::runtime_error("no record for " + topic + " in " + out_dir.string());
    typename runtime::PubSubTypeOf<T>::type ps;
    std::vector<T> out;
    while (true) {
        std::uint8_t head[12];
        if (!f.read(reinterpret_cast<char*>(head), sizeof(head))) break;
        std::uint32_t n = 0;
        for (int i = 0; i < 4; ++i) n |= static_cast<std::uint32_t>(head[8 + i]) << (8 * i);
        eprosima::fastrtps::rtps::SerializedPayload_t payload(n);
        if (!f.read(reinterpret_cast<char*>(payload.data), n)) break;
        payload.length = n;
        T sample;
        ps.deserialize(&payload, &sample);
        out.push_back(sample);
    }
    return out;
}

}  // namespace gdnav::testing
