#pragma once
// A DDS reader outside a run (a monitoring tool, not a member): takes every valid sample while the run's launcher
// runs, and after it ended until nothing is left. Used by the composed-visibility, stride-reader and mirror tests.
#include <sys/types.h>

#include <chrono>
#include <cstdint>
#include <functional>
#include <string>
#include <thread>

#include <fastdds/dds/domain/DomainParticipant.hpp>
#include <fastdds/dds/subscriber/DataReader.hpp>
#include <fastdds/dds/subscriber/SampleInfo.hpp>
#include <fastdds/dds/subscriber/Subscriber.hpp>
#include <fastdds/dds/subscriber/qos/DataReaderQos.hpp>

#include "dds/dds_context.hpp"
#include "process_util.hpp"
#include "msgs/message_ops.hpp"

namespace gdnav::testing {

// A reader of `topic` with the data readers' QoS but a history that keeps `samples` samples (nullptr: not created).
// A reader outside the lockstep may not be scheduled for longer than the profile's 72 samples take to arrive on a
// loaded machine: its receive thread then replaces samples that the test has not taken yet. The run's writers never
// wait for it, so what it must keep is its own affair.
inline eprosima::fastdds::dds::DataReader* whole_run_reader(dds::DdsContext& dds, const std::string& topic,
                                                            const msg::MessageOps& ops, std::int32_t samples) {
    using namespace eprosima::fastdds::dds;
    // The context's reader registers the type and creates the topic; it is then replaced by the deep one.
    DataReader* shallow = dds.reader(topic, ops, dds::kDataReaderProfile);
    auto* subscriber = const_cast<Subscriber*>(shallow->get_subscriber());
    DataReaderQos q;
    if (subscriber->get_datareader_qos_from_profile(dds::kDataReaderProfile, q) !=
            eprosima::fastrtps::types::ReturnCode_t::RETCODE_OK ||
        subscriber->delete_datareader(shallow) != eprosima::fastrtps::types::ReturnCode_t::RETCODE_OK)
        return nullptr;
    q.history().depth = samples;
    q.resource_limits().max_samples = samples;
    q.resource_limits().max_samples_per_instance = samples;
    return subscriber->create_datareader(dds.participant()->lookup_topicdescription(topic), q);
}

// Calls on_sample(the sample, of ops' type) for each sample; returns the launcher's exit code (-1: still running
// after timeout_s plus 5 s).
inline int read_samples_while_running(pid_t launcher, eprosima::fastdds::dds::DataReader& reader,
                                      const msg::MessageOps& ops, double timeout_s,
                                      const std::function<void(const void*)>& on_sample) {
    using eprosima::fastdds::dds::SampleInfo;
    void* sample = ops.create();
    int code = -1;
    const auto deadline = std::chrono::steady_clock::now() + std::chrono::duration<double>(timeout_s);
    while (std::chrono::steady_clock::now() < deadline) {
        SampleInfo info;
        bool any = false;
        while (reader.take_next_sample(sample, &info) == eprosima::fastrtps::types::ReturnCode_t::RETCODE_OK) {
            if (!info.valid_data) continue;
            on_sample(sample);
            any = true;
        }
        if (!any) {
            if (code != -1) break;  // the run ended and everything it sent is read
            code = wait_for(launcher, 0.0);  // has it ended?
            std::this_thread::sleep_for(std::chrono::milliseconds(1));
        }
    }
    if (code == -1) code = wait_for(launcher, 5.0);
    ops.destroy(sample);
    return code;
}

// As read_samples_while_running, with on_step(step of the sample).
inline int read_while_running(pid_t launcher, eprosima::fastdds::dds::DataReader& reader,
                              const msg::MessageOps& ops, double timeout_s,
                              const std::function<void(std::uint64_t)>& on_step) {
    return read_samples_while_running(launcher, reader, ops, timeout_s,
                                      [&](const void* sample) { on_step(ops.step_of(sample)); });
}

}  // namespace gdnav::testing
