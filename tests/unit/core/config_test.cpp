#include <gtest/gtest.h>

#include <functional>

#include "config/config.hpp"

using gdnav::config::Config;
using gdnav::config::ConfigError;
using gdnav::config::Range;

namespace {
std::string error_of(const std::string& yaml, const std::function<void(const Config&)>& f) {
    try {
        f(Config::parse(yaml, "test.yaml"));
    } catch (const ConfigError& e) {
        return e.what();
    }
    return "";
}
}  // namespace

TEST(Config, ReadsValues) {
    const Config c = Config::parse("a: 1.5\nb: {c: [1, 2, 3]}\nname: x\n", "t.yaml");
    EXPECT_EQ(c.get_double("a", Range::nonneg()), 1.5);
    EXPECT_EQ(c.child("b").get_vec3("c").z(), 3.0);
    EXPECT_EQ(c.get_choice("name", {"x", "y"}), "x");
    EXPECT_NO_THROW(c.finish());
}

TEST(Config, MissingKeyNamesFileAndKey) {
    const auto e = error_of("a: 1\n", [](const Config& c) { c.child("s").get_double("sigma"); });
    EXPECT_NE(e.find("test.yaml"), std::string::npos);
    EXPECT_NE(e.find("'s'"), std::string::npos);
}

TEST(Config, OutOfRangeNamesRange) {
    const auto e = error_of("s: {sigma: -1}\n", [](const Config& c) { c.child("s").get_double("sigma", Range::nonneg()); });
    EXPECT_NE(e.find("'s.sigma'"), std::string::npos) << e;
    EXPECT_NE(e.find("[0, inf)"), std::string::npos) << e;
}

TEST(Config, WrongTypeAndUnknownKeyAndMalformed) {
    EXPECT_NE(error_of("n: abc\n", [](const Config& c) { c.get_int("n", 0, 10); }).find("integer"), std::string::npos);
    EXPECT_NE(error_of("n: 1\ntypo: 2\n", [](const Config& c) { c.get_int("n", 0, 10); c.finish(); }).find("'typo': unknown key"),
              std::string::npos);
    EXPECT_NE(error_of("n: [1, 2\n", [](const Config&) {}).find("malformed"), std::string::npos);
    EXPECT_NE(error_of("m: x\n", [](const Config& c) { c.get_choice("m", {"a", "b"}); }).find("{a, b}"), std::string::npos);
}
