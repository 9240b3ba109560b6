// Specs cut into datagram-sized chunks and put together again, in any order, with their
// content hash checked.

#include "cluster/spec_chunks.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <random>

namespace envdesign::cluster {
namespace {

std::string bytes_of(std::size_t size) {
    std::string s(size, '\0');
    std::mt19937 random(42);
    for (auto &c : s)
        c = static_cast<char>(random());
    return s;
}

TEST(SpecChunks, HashIsSha256Hex) {
    EXPECT_EQ(content_hash("abc"),
              "ba7816bf8f01cfea414140de5dae2223b00361a396177a9cb410ff61f20015ad");
}

TEST(SpecChunks, SplitAndAssembleInAnyOrder) {
    std::string bytes = bytes_of(3 * CHUNK_BYTES + 17);
    std::string hash = content_hash(bytes);
    auto chunks = split_spec(bytes, hash, 1, "coordinator");
    ASSERT_EQ(chunks.size(), 4u);
    for (const auto &c : chunks) {
        EXPECT_FALSE(chunk_problem(c));
        EXPECT_LE(c.num_bytes, CHUNK_BYTES);
    }
    std::reverse(chunks.begin(), chunks.end());
    SpecAssembler a(chunks[0]);
    for (std::size_t i = 0; i < chunks.size(); ++i) {
        EXPECT_FALSE(a.complete());
        EXPECT_TRUE(a.add(chunks[i]));
        EXPECT_TRUE(a.add(chunks[i])); // a duplicate changes nothing
    }
    ASSERT_TRUE(a.complete());
    EXPECT_EQ(a.bytes(), bytes);
    EXPECT_TRUE(a.missing().empty());
}

TEST(SpecChunks, OnlyTheChunksAskedFor) {
    std::string bytes = bytes_of(2 * CHUNK_BYTES + 1);
    auto chunks = split_spec(bytes, content_hash(bytes), 1, "c", {2, 7, -1});
    ASSERT_EQ(chunks.size(), 1u);
    EXPECT_EQ(chunks[0].chunk_index, 2);
    SpecAssembler a(chunks[0]);
    EXPECT_TRUE(a.add(chunks[0]));
    EXPECT_EQ(a.missing(), (std::vector<int>{0, 1}));
}

TEST(SpecChunks, InconsistentChunksAreRejected) {
    std::string bytes = bytes_of(CHUNK_BYTES + 5);
    auto chunks = split_spec(bytes, content_hash(bytes), 1, "c");
    auto bad = chunks[1];
    bad.num_bytes = 4;
    EXPECT_TRUE(chunk_problem(bad));
    bad = chunks[0];
    bad.num_chunks = 3;
    EXPECT_TRUE(chunk_problem(bad));
    bad = chunks[0];
    bad.spec_hash = "short";
    EXPECT_TRUE(chunk_problem(bad));
    SpecAssembler a(chunks[0]);
    auto other = split_spec(bytes + "more", content_hash(bytes + "more"), 1, "c");
    EXPECT_FALSE(a.add(other[1])); // another size
}

} // namespace
} // namespace envdesign::cluster
