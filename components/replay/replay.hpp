#pragma once
// replay: publishes recorded topics at their recorded steps, so that consumers (navigation filters, built-in or
// external) run against recorded data without the producers (physics, sensors). docs/replay.md.
//
//   replay: {type: replay, record: out/run1/record, topics: [gdnav/ImuSample, MagSample, ...]}
//
// Configure reads <record>/run.mcap fully (the runtime recorder's MCAP recording, record_file.hpp) and checks it:
// every channel is a gdnav topic (an MCAP of another tool is refused, naming the channel), each replayed topic has
// a channel whose messages are well formed, match their digest in <record>/digest.yaml when listed there, start at
// step 0, reach the run's last step, and are stamped with this run's time grid (t0_s + k dt_s). One ConfigError
// naming the file and the key otherwise. A file cut short (run killed) is read up to the cut, with a warning.
//
// Step k publishes the sample recorded for step k. A step without a record (a recorder with decimation, or gaps in
// an imported log) publishes the latest recorded sample before it again (zero-order hold, restamped by the executor
// with step k); the number of held steps per topic is logged at step 0. A record must cover the run's last step: a
// producer that died mid-run cannot be replayed past its last sample (shorten the run with --steps).
#include <memory>
#include <string>
#include <vector>

#include "io/recording/record_file.hpp"
#include "framework/component.hpp"
#include "framework/registry.hpp"

namespace gdnav::replay {

// The record files are the recorder's format (common/io/recording/record_file.hpp).
using io::recording::SampleDecoder;
using io::recording::TopicRecord;

class Replay final : public framework::Component {
public:
    explicit Replay(std::string name);
    ~Replay() override;
    void configure(const config::Config& cfg, const framework::RunInfo& run, rnd::Stream& stream) override;
    void step(const framework::StepContext& ctx) override;

private:
    class RecordedOutput;
    struct Track {
        TopicRecord record;
        std::unique_ptr<RecordedOutput> output;
        std::unique_ptr<SampleDecoder> decoder;
        std::size_t next{0};  // first entry not yet published
        std::uint64_t held_steps{0};
        std::uint64_t largest_gap{0};
    };
    std::vector<std::unique_ptr<Track>> tracks_;
    bool reported_{false};
};

void register_replay(framework::ComponentRegistry& reg);

}  // namespace gdnav::replay
