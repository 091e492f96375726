#pragma once
// Which samples an executor delivers to an input whose member uses only every N-th step (InputBase::set_stride).
// One rule for every executor, so that an observer sees the same steps in every layout; its bounds come from the
// DDS transport.
//
// The member then reads only the samples of steps k with k % stride == 0 (k of the sample: k - 1 for Lag::Previous);
// at the other steps the input is absent and never waited for. The reader asks the producers' writers to send only
// those steps (a writer-side content filter, dds/filters/stride_filter.hpp), so the member does not receive the
// samples between; an observer's input at stride 10 reads the producers' decimated mirror of the topic instead where
// they write one (dds/host/mirror.hpp). The stride taken for a wish of N is the largest divisor of N in
// [kMinStride, kMaxStride], or 1 (every sample) when N has none. Why these bounds: with Fast DDS 2.9.1 a writer that
// filters for a reader still sends it GAP/HEARTBEAT traffic for the skipped samples; beyond a stride of about 10 that
// traffic outweighs the samples saved, and at stride 2 it costs more than sending everything
// (docs/notes/runtime-measurements.md, "Which strides pay").
#include <cstdint>

#include "framework/compat.hpp"
#include "framework/component.hpp"

namespace gdnav::framework {

inline constexpr std::uint64_t kMinStride = 4;
inline constexpr std::uint64_t kMaxStride = 10;

// The stride a DDS host reads at for a member that uses every N-th step.
[[nodiscard]] constexpr std::uint64_t effective_stride(std::uint64_t n) {
    for (std::uint64_t d = n < kMaxStride ? n : kMaxStride; d >= kMinStride; --d)
        if (n % d == 0) return d;
    return 1;
}

[[nodiscard]] inline std::uint64_t stride_of(const InputBase& in) { return effective_stride(in.wanted_stride()); }

// True when the input reads the sample of SAMPLE_STEP.
[[nodiscard]] inline bool on_stride(const InputBase& in, std::uint64_t sample_step) {
    const std::uint64_t s = stride_of(in);
    return s == 1 || sample_step % s == 0;
}

}  // namespace gdnav::framework
