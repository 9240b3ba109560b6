// Key files: the format, and permissions that refuse a key others can read.

#include "bus/key_file.h"

#include <gtest/gtest.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sys/stat.h>
#include <unistd.h>

namespace envdesign::bus {
namespace {

const std::string HEX_A(64, 'a');
const std::string HEX_B = std::string(62, '0') + "1f";

std::string error_of(const std::string &text) {
    try {
        parse_key_ring(text, "keys");
    } catch (const KeyFileError &e) {
        return e.what();
    }
    return "";
}

TEST(KeyFile, ParsesKeysInOrderSkippingCommentsAndBlanks) {
    KeyRing ring =
        parse_key_ring("# rotation\n\nnew " + HEX_A + "\n  old " + HEX_B + "\r\n", "keys");
    ASSERT_EQ(ring.keys.size(), 2u);
    EXPECT_EQ(ring.keys[0].id, "new");
    EXPECT_EQ(ring.keys[0].secret, std::string(32, '\xaa'));
    EXPECT_EQ(ring.keys[1].id, "old");
    EXPECT_EQ(ring.keys[1].secret.back(), '\x1f');
    EXPECT_EQ(ring.find("old"), &ring.keys[1]);
    EXPECT_EQ(ring.find("none"), nullptr);
}

TEST(KeyFile, RejectsMalformedLinesWithTheirLine) {
    EXPECT_EQ(error_of(""), "keys: no key (expected lines 'KEY_ID HEX_SECRET')");
    EXPECT_EQ(error_of("# only\nk1\n"), "keys:2: expected 'KEY_ID HEX_SECRET'");
    EXPECT_EQ(error_of("k1 " + HEX_A + " extra"), "keys:1: expected 'KEY_ID HEX_SECRET'");
    EXPECT_NE(error_of("toolongid " + HEX_A).find("is not 1-8"), std::string::npos);
    EXPECT_NE(error_of("k/1 " + HEX_A).find("is not 1-8"), std::string::npos);
    EXPECT_NE(error_of("k1 " + std::string(64, 'g')).find("not hexadecimal"), std::string::npos);
    EXPECT_NE(error_of("k1 abc").find("not hexadecimal"), std::string::npos);
    EXPECT_NE(error_of("k1 " + std::string(62, 'a')).find("has 31 bytes"), std::string::npos);
    EXPECT_NE(error_of("k1 " + HEX_A + "\nk1 " + HEX_B).find("appears twice"), std::string::npos);
    std::string nine;
    for (int i = 0; i < 9; ++i)
        nine += "k" + std::to_string(i) + " " + HEX_A + "\n";
    EXPECT_NE(error_of(nine).find("keys:9: more than 8 keys"), std::string::npos);
}

class KeyFileOnDisk : public ::testing::Test {
protected:
    void SetUp() override {
        path_ =
            std::filesystem::temp_directory_path() / ("envdesign-keys-" + std::to_string(getpid()));
        std::ofstream(path_) << "k1 " << HEX_A << "\n";
    }
    void TearDown() override { std::filesystem::remove(path_); }
    std::string load_error() {
        try {
            load_key_file(path_);
        } catch (const KeyFileError &e) {
            return e.what();
        }
        return "";
    }
    std::string path_;
};

TEST_F(KeyFileOnDisk, LoadsAnOwnerOnlyFile) {
    ::chmod(path_.c_str(), 0600);
    EXPECT_EQ(load_key_file(path_).keys.at(0).id, "k1");
    ::chmod(path_.c_str(), 0400);
    EXPECT_EQ(load_key_file(path_).keys.size(), 1u);
}

TEST_F(KeyFileOnDisk, RefusesAFileGroupOrOthersCanAccess) {
    for (mode_t mode : {0640, 0604, 0660, 0602, 0644}) {
        ::chmod(path_.c_str(), mode);
        EXPECT_NE(load_error().find("accessible by group or others"), std::string::npos)
            << std::oct << mode;
    }
}

TEST_F(KeyFileOnDisk, RefusesWhatIsNotARegularFile) {
    std::string dir = path_ + ".d";
    std::filesystem::create_directory(dir);
    ::chmod(dir.c_str(), 0700);
    try {
        load_key_file(dir);
        ADD_FAILURE() << "a directory was taken as a key file";
    } catch (const KeyFileError &e) {
        EXPECT_NE(std::string(e.what()).find("not a regular file"), std::string::npos);
    }
    std::filesystem::remove(dir);
    EXPECT_THROW(load_key_file(path_ + ".missing"), KeyFileError);
}

TEST(KeyFilePath, FlagBeforeEnvironment) {
    ::unsetenv("ENVDESIGN_KEY_FILE");
    EXPECT_FALSE(key_file_path(""));
    ::setenv("ENVDESIGN_KEY_FILE", "/etc/envdesign/bus.key", 1);
    EXPECT_EQ(key_file_path(""), "/etc/envdesign/bus.key");
    EXPECT_EQ(key_file_path("mine.key"), "mine.key");
    ::setenv("ENVDESIGN_KEY_FILE", "", 1);
    EXPECT_FALSE(key_file_path(""));
    ::unsetenv("ENVDESIGN_KEY_FILE");
}

} // namespace
} // namespace envdesign::bus
