#include <cstdio>
#include <cstdlib>
#include <stdexcept>

#include "gdnav/client/member.hpp"

namespace gdnav::client {

namespace {

template <class T>
T parse_number(const std::string& flag, const std::string& text, T lo, T hi) {
    std::size_t used = 0;
    long double v = 0;
    try {
        v = std::stold(text, &used);
    } catch (const std::exception&) {
        used = 0;
    }
    if (used != text.size() || text.empty() || v < static_cast<long double>(lo) || v > static_cast<long double>(hi))
        throw std::invalid_argument(flag + " " + text + ": expected a number in [" + std::to_string(lo) + ", " +
                                    std::to_string(hi) + "]");
    return static_cast<T>(v);
}

// A member started by gdnav (run.members) finds the run's settings in its environment (docs/external.md).
void apply_environment(Options& o) {
    auto env = [](const char* name) -> const char* {
        const char* v = std::getenv(name);
        return v && *v ? v : nullptr;
    };
    if (const char* v = env("GDNAV_MEMBER")) o.name = v;
    if (const char* v = env("GDNAV_DOMAIN")) o.domain_id = parse_number<int>("environment GDNAV_DOMAIN", v, 0, 232);
    if (const char* v = env("GDNAV_RUN"))
        o.run_id = parse_number<std::uint64_t>("environment GDNAV_RUN", v, 0, 1'000'000'000);
    if (const char* v = env("GDNAV_SECURITY")) o.security = v;
    if (const char* v = env("GDNAV_DDS_PROFILE")) o.dds_profile = v;
}

}  // namespace

std::string Options::usage(const std::string& program) {
    return "usage: " + program +
           " [--name NAME] [--domain D] [--run I] [--free-running] [--dds-profile FILE] [--security DIR] "
           "[--startup-timeout S] "
           "[--log-level trace|debug|info|warn|error]";
}

Options Options::from_args(int argc, const char* const* argv, std::string default_name, std::vector<std::string>* extra) {
    Options o;
    o.name = std::move(default_name);
    apply_environment(o);  // then the flags, which win
    const std::string program = argc > 0 ? argv[0] : "member";
    for (int i = 1; i < argc; ++i) {
        const std::string a = argv[i];
        auto value = [&]() -> std::string {
            if (i + 1 >= argc) throw std::invalid_argument(a + ": missing value (" + usage(program) + ")");
            return argv[++i];
        };
        if (a == "--help" || a == "-h") {
            std::fprintf(stdout, "%s\n", usage(program).c_str());
            std::exit(0);
        } else if (a == "--name") {
            o.name = value();
        } else if (a == "--domain") {
            o.domain_id = parse_number<int>(a, value(), 0, 232);
        } else if (a == "--run") {
            o.run_id = parse_number<std::uint64_t>(a, value(), 0, 1'000'000'000);
        } else if (a == "--free-running") {
            o.free_running = true;
        } else if (a == "--dds-profile") {
            o.dds_profile = value();
        } else if (a == "--security") {
            o.security = value();
        } else if (a == "--startup-timeout") {
            o.startup_timeout_s = parse_number<double>(a, value(), 1.0, 86400.0);
        } else if (a == "--log-level") {
            o.log_level = value();
            if (o.log_level != "trace" && o.log_level != "debug" && o.log_level != "info" && o.log_level != "warn" &&
                o.log_level != "error" && o.log_level != "off")
                throw std::invalid_argument("--log-level " + o.log_level + ": expected trace, debug, info, warn, error or off");
        } else if (extra && a.rfind("--x-", 0) == 0) {
            extra->push_back(a);
            if (i + 1 < argc && std::string(argv[i + 1]).rfind("--", 0) != 0) extra->push_back(argv[++i]);
        } else {
            throw std::invalid_argument("unknown argument '" + a + "' (" + usage(program) + ")");
        }
    }
    return o;
}

}  // namespace gdnav::client
