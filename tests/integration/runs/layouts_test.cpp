// Same seed -> bit-identical recorded outputs in the direct, composed and distributed layouts (and twice in a
// row); another seed -> different outputs. Real processes, real DDS.
#include <gtest/gtest.h>

#include "process_util.hpp"

using namespace gdnav::testing;

namespace {
std::map<std::string, std::string> run_layout(const std::string& layout, int seed, const std::string& tag) {
    const auto out = temp_dir(tag);
    const Result r = run({testchain_exe(), "run", "--scenario", chain_scenario(), "--layout", layout, "--seed",
                          std::to_string(seed), "--out", out.string()},
                         120.0);
    EXPECT_EQ(r.exit_code, 0) << r.output;
    const auto d = read_digests(out);
    EXPECT_EQ(d.size(), 4u) << r.output;
    return d;
}
}  // namespace

TEST(Layouts, SameSeedBitIdenticalInAllLayoutsOtherSeedDiffers) {
    const auto direct = run_layout("direct", 1, "direct");
    const auto direct2 = run_layout("direct", 1, "direct2");
    const auto composed = run_layout("composed", 1, "composed");
    const auto distributed = run_layout("distributed", 1, "distributed");
    const auto distributed2 = run_layout("distributed", 1, "distributed2");
    const auto other = run_layout("direct", 2, "other");
    EXPECT_EQ(direct, direct2);
    EXPECT_EQ(direct, composed);
    EXPECT_EQ(direct, distributed);
    EXPECT_EQ(direct, distributed2);
    for (const auto& [topic, digest] : direct) EXPECT_NE(other.at(topic), digest) << topic;
}
