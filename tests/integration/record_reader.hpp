#pragma once
// Reads one topic of the runtime recorder's recording (<out>/record/run.mcap) back into IDL messages, with gdnav's
// own MCAP reader (common/io/recording/record_file.hpp).
#include <filesystem>
#include <stdexcept>
#include <vector>

#include "io/recording/record_file.hpp"
#include "msgs/messages.hpp"
#include "framework/topic_types.hpp"

namespace gdnav::testing {

template <class T>
std::vector<T> read_records(const std::filesystem::path& out_dir, const std::string& topic) {
    framework::register_gdnav_topics();
    const io::recording::TopicRecord r = io::recording::read_topic_record(out_dir / "record", topic);
    io::recording::SampleDecoder decoder(*r.ops);
    std::vector<T> out;
    for (const auto& e : r.entries) {
        T sample;
        if (!decoder.decode(&r.bytes[e.offset], e.size, &sample))
            throw std::runtime_error(topic + ": cannot decode the sample of step " + std::to_string(e.step));
        out.push_back(sample);
    }
    return out;
}

}  // namespace gdnav::testing
