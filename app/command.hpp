#pragma once
// A gdnav subcommand: each lives in its own file and registers itself with the CLI11 app. The returned function
// runs it (after parsing) and returns the exit code; configuration errors are reported by cli_main.
#include <functional>
#include <string>

#include <CLI/CLI.hpp>

#include "framework/registry.hpp"

namespace gdnav::cli {

struct CliContext {
    const framework::ComponentRegistry& registry;
    std::string log_level{"info"};
    std::string program;  // argv[0] name, for messages
};

using CommandRunner = std::function<int()>;

// Registers a subcommand on `app`; returns the subcommand and sets `run` to its action.
using CommandFactory = CLI::App* (*)(CLI::App& app, CliContext& ctx, CommandRunner& run);

// Sets up spdlog for this process ("[time] [who] level: message").
void setup_logging(const std::string& who, const std::string& level);

}  // namespace gdnav::cli
