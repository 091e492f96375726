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

// Numbers are finite whatever the range (scalars, lists, vectors, matrices, ints).
TEST(Config, NanAndInfinitiesAreRejectedByEveryNumericGetter) {
    for (const char* bad : {".nan", ".NaN", ".inf", "-.inf", "+.inf", "1e999"}) {
        const std::string v(bad);
        SCOPED_TRACE(v);
        EXPECT_NE(error_of("a: " + v + "\n", [](const Config& c) { (void)c.get_double("a"); }).find("key 'a'"),
                  std::string::npos);
        EXPECT_NE(error_of("a: " + v + "\n", [](const Config& c) { (void)c.get_double("a", 1.0, Range{}); })
                      .find("key 'a'"),
                  std::string::npos);
        EXPECT_NE(error_of("a: " + v + "\n", [](const Config& c) { (void)c.get_angle_deg("a"); }).find("key 'a'"),
                  std::string::npos);
        EXPECT_NE(error_of("a: " + v + "\n", [](const Config& c) { (void)c.get_int("a", -10, 10); }).find("key 'a'"),
                  std::string::npos);
        EXPECT_NE(error_of("a: " + v + "\n", [](const Config& c) { (void)c.get_uint64("a"); }).find("key 'a'"),
                  std::string::npos);
        EXPECT_NE(error_of("a: [1, " + v + ", 3]\n", [](const Config& c) { (void)c.get_vec3("a"); })
                      .find("key 'a': element 1"),
                  std::string::npos);
        EXPECT_NE(error_of("a: [1, 0, 0, 0, 1, 0, 0, 0, " + v + "]\n", [](const Config& c) { (void)c.get_mat3("a"); })
                      .find("key 'a': element 8"),
                  std::string::npos);
    }
    EXPECT_NE(error_of("a: [1, [2], 3]\n", [](const Config& c) { (void)c.get_vec3("a"); }).find("element 1"),
              std::string::npos);
}

TEST(Config, DuplicateAndNonScalarKeysAreRejected) {
    EXPECT_NE(error_of("a: 1\nb: {c: 1, c: 2}\n", [](const Config&) {}).find("key 'b.c': duplicate key"),
              std::string::npos);
    EXPECT_NE(error_of("a: 1\na: 2\n", [](const Config&) {}).find("key 'a': duplicate key"), std::string::npos);
    EXPECT_NE(error_of("l: [{x: 1, x: 1}]\n", [](const Config&) {}).find("key 'l[0].x': duplicate key"),
              std::string::npos);
    EXPECT_NE(error_of("? [1, 2]\n: 3\n", [](const Config&) {}).find("not a plain name"), std::string::npos);
}

TEST(Config, ErrorsAreOneLine) {
    const std::string e = error_of("a: \"x\\ny\"\n", [](const Config& c) { (void)c.get_choice("a", {"x"}); });
    EXPECT_NE(e.find("'x\\ny'"), std::string::npos) << e;
    EXPECT_EQ(e.find('\n'), std::string::npos) << e;
    EXPECT_EQ(std::string(ConfigError("a\nb\x01").what()), "a\\nb\\x01");
}

TEST(Config, FilesAreCheckedWhereTheyAreNamed) {
    const std::string e = error_of("f: no/such/file.yaml\n", [](const Config& c) { (void)c.get_file("f", "/tmp"); });
    EXPECT_NE(e.find("key 'f': no such file '/tmp/no/such/file.yaml'"), std::string::npos) << e;
    const Config c = Config::parse("g: x\n", "t.yaml");
    EXPECT_EQ(c.get_file("f", "default.yaml", "/dir"), std::filesystem::path("/dir/default.yaml"));  // not checked
}
