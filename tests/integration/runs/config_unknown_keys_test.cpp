// Unknown keys in config/nav/tuning.yaml and the variant files are rejected anywhere in the file, also outside the
// section a nav component reads: each file is validated whole (a finding of the config fuzzer's user trial).
#include <gtest/gtest.h>

#include "commands.hpp"
#include "config/config.hpp"
#include "config_mutation.hpp"

namespace fs = std::filesystem;
using namespace gdnav::testing::fuzz;

TEST(ConfigFuzz, NavTuningAndVariantFilesRejectUnknownKeysAnywhere) {
    gdnav::framework::ComponentRegistry reg;
    const fs::path tmp = private_config("cfg_nav", reg);
    const fs::path cfg = tmp / "config";

    struct NavCase {
        std::string file, append, key;
    };
    const std::vector<NavCase> cases{
        {"nav/tuning.yaml", "atitude: {dt_s: 0.01}\n", "atitude"},
        {"nav/tuning.yaml", "extra: 1\n", "extra"},
        {"nav/variants/baseline.yaml", "air: {model: x}\n", "air"},
        {"nav/variants/hor_double_integration.yaml", "postion: {horizontal: frozen_wind}\n", "postion"},
    };
    for (const auto& c : cases) {
        SCOPED_TRACE(c.file + " + " + c.append);
        const fs::path file = cfg / c.file;
        const std::string original = read_text(file);
        write_text(file, original + c.append);
        const bool variant = c.file != "nav/tuning.yaml";
        if (variant)
            write_derived_scenario(cfg, "fuzz_nav", {{"nav_att", "variant", c.file}, {"nav_pos", "variant", c.file}});
        std::string error;
        try {
            (void)gdnav::cli::validate_scenario(variant ? "fuzz_nav" : "paper2", reg);
        } catch (const gdnav::config::ConfigError& e) {
            error = e.what();
        }
        write_text(file, original);
        EXPECT_NE(error.find(file.string() + ": key '" + c.key + "': unknown key"), std::string::npos) << error;
    }
    fs::remove_all(tmp);
}
