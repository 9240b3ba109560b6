#include "search/int_packer.h"

#include <gtest/gtest.h>

#include <random>

namespace envdesign::search {
namespace {

TEST(IntPacker, BitWidths) {
    IntPacker packer({1, 2, 3, 4, 5, 8, 9, 1 << 20, (1 << 20) + 1});
    EXPECT_EQ(packer.bits(0), 0);
    EXPECT_EQ(packer.bits(1), 1);
    EXPECT_EQ(packer.bits(2), 2);
    EXPECT_EQ(packer.bits(3), 2);
    EXPECT_EQ(packer.bits(4), 3);
    EXPECT_EQ(packer.bits(5), 3);
    EXPECT_EQ(packer.bits(6), 4);
    EXPECT_EQ(packer.bits(7), 20);
    EXPECT_EQ(packer.bits(8), 21);
}

TEST(IntPacker, SmallVariablesShareOneBin) {
    EXPECT_EQ(IntPacker({3, 2, 5}).num_bins(), 1); // 2 + 1 + 3 bits
    EXPECT_EQ(IntPacker(std::vector<int>(32, 2)).num_bins(), 1);
    EXPECT_EQ(IntPacker(std::vector<int>(33, 2)).num_bins(), 2);
    EXPECT_EQ(IntPacker({}).num_bins(), 0);
}

// Three 17-bit variables cannot share bins (no straddling); the 15 one-bit variables then
// fill the gaps first-fit instead of opening a fourth bin.
TEST(IntPacker, NoStraddlingAndFirstFitDecreasing) {
    std::vector<int> ranges(15, 2);
    ranges.insert(ranges.begin() + 5, {1 << 17, 1 << 17, 1 << 17});
    IntPacker packer(ranges);
    EXPECT_EQ(packer.num_bins(), 3);
}

TEST(IntPacker, RandomRoundTrip) {
    std::mt19937 rng(1);
    for (int round = 0; round < 50; ++round) {
        std::uniform_int_distribution<int> num_vars(1, 40), log_range(0, 31);
        std::vector<int> ranges(num_vars(rng));
        for (int &r : ranges) {
            int bits = log_range(rng);
            r = bits == 31 ? 0x7fffffff
                           : (1 << bits) + std::uniform_int_distribution<int>(0, 2)(rng);
        }
        IntPacker packer(ranges);
        std::vector<IntPacker::Bin> bins(packer.num_bins(), 0xdeadbeef);
        std::vector<int> values(ranges.size());
        for (int pass = 0; pass < 3; ++pass) {
            for (std::size_t v = 0; v < ranges.size(); ++v) {
                values[v] = std::uniform_int_distribution<int>(0, ranges[v] - 1)(rng);
                packer.set(bins.data(), static_cast<int>(v), values[v]);
            }
            for (std::size_t v = 0; v < ranges.size(); ++v)
                ASSERT_EQ(packer.get(bins.data(), static_cast<int>(v)), values[v]);
        }
    }
}

TEST(IntPacker, InvalidRangesThrow) { EXPECT_THROW(IntPacker({0}), std::invalid_argument); }

} // namespace
} // namespace envdesign::search
