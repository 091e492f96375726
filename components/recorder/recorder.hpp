#pragma once
// recorder: subscribes to a configured list of topics and writes, per topic, every sample in lockstep order.
//
// Files in <out_dir>/record/:
//   <topic>.cdr   — one record per step: u64 step (little endian), u32 n, n bytes of the sample's CDR encoding
//                   (padding zeroed, so identical samples give identical bytes). '/' in topic names becomes '__'.
//   digest.yaml   — per topic: samples, last_step, FNV-1a 64 digest of all its records; `complete: true` only when
//                   the run finished normally. Two runs are bit-identical iff their digests are equal.
// Inputs whose producer dies are recorded up to the last step they delivered (`lost_at_step` in the digest).
#include <cstdint>
#include <memory>
#include <vector>

#include "record_file.hpp"
#include "runtime/component.hpp"
#include "runtime/registry.hpp"

namespace gdnav::recorder {

class Recorder final : public runtime::Component {
public:
    explicit Recorder(std::string name) : Component(std::move(name)) {}
    void configure(const config::Config& cfg, const runtime::RunInfo& run, rnd::Stream& stream) override;
    void step(const runtime::StepContext& ctx) override;
    void finish(bool completed) override;

private:
    struct Track {
        std::unique_ptr<runtime::InputBase> input;
        std::unique_ptr<RecordWriter> writer;  // opened at the first step (record_file.hpp: the file format)
        bool lost_reported{false};
        std::uint64_t lost_at{0};
    };
    void open_files();
    std::vector<std::unique_ptr<Track>> tracks_;
    std::string dir_;
    std::uint64_t decimation_{1};
    bool finished_{false};
};

void register_recorder(runtime::ComponentRegistry& reg);

}  // namespace gdnav::recorder
