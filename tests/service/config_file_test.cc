// Service config files (service/config_file.h): settings, comments, quotes, and errors
// that name FILE:LINE:COL.

#include "service/config_file.h"

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>

namespace envdesign::service {
namespace {

std::string write(const std::string &name, const std::string &text) {
    auto path = std::filesystem::path(::testing::TempDir()) / name;
    std::ofstream(path) << text;
    return path.string();
}

std::string error_of(const std::string &path) {
    try {
        read_config_file(path);
    } catch (const ConfigError &e) {
        return e.what();
    }
    return "";
}

TEST(ConfigFile, SettingsCommentsAndQuotes) {
    std::string path = write("good.conf", "# a comment\n"
                                          "\n"
                                          "max-requests = 4   # trailing comment\n"
                                          "  lcm-url=\"udpm://239.255.76.67:7667?ttl=0 # kept\"\n"
                                          "problem = a=/x/a.textproto\n"
                                          "problem = b=/x/b.textproto\r\n"
                                          "empty =\n");
    std::vector<ConfigSetting> s = read_config_file(path);
    ASSERT_EQ(s.size(), 5u);
    EXPECT_EQ(s[0].key, "max-requests");
    EXPECT_EQ(s[0].value, "4");
    EXPECT_EQ(s[0].line, 3);
    EXPECT_EQ(s[0].key_column, 1);
    EXPECT_EQ(s[1].key, "lcm-url");
    EXPECT_EQ(s[1].value, "udpm://239.255.76.67:7667?ttl=0 # kept");
    EXPECT_EQ(s[1].key_column, 3);
    EXPECT_EQ(s[2].value, "a=/x/a.textproto"); // the first '=' separates
    EXPECT_EQ(s[3].value, "b=/x/b.textproto"); // a Windows line end is no part of it
    EXPECT_EQ(s[4].key, "empty");
    EXPECT_EQ(s[4].value, "");
}

TEST(ConfigFile, ErrorsNameFileLineAndColumn) {
    std::string missing = write("missing.conf", "log-level = info\nmax-requests 4\n");
    EXPECT_EQ(error_of(missing), missing + ":2:14: error: expected '=' after 'max-requests'");
    std::string name = write("name.conf", "  --max-requests = 4\n");
    EXPECT_EQ(error_of(name),
              name + ":1:3: error: expected a setting name (a flag's name, no dashes)");
    std::string quote = write("quote.conf", "name = \"coordinator/a\n");
    EXPECT_EQ(error_of(quote), quote + ":1:7: error: unterminated quote");
    std::string after = write("after.conf", "name = \"a\" b\n");
    EXPECT_EQ(error_of(after), after + ":1:7: error: text after the closing quote");
    std::string absent = (std::filesystem::path(::testing::TempDir()) / "absent.conf").string();
    EXPECT_EQ(error_of(absent), absent + ": error: cannot read the config file");
}

} // namespace
} // namespace envdesign::service
