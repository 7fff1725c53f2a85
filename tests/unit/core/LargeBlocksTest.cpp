// SPDX-License-Identifier: MIT
// Copyright (c) 2026 The Q3 authors

// core/LargeBlocks: large data arrays are recycled (the same block comes back
// for a similar size), small ones and very different sizes are not, and the
// cache stays within its block count.

#include "core/LargeBlocks.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cstdlib>
#include <cstring>
#include <vector>

namespace {

using namespace q3::memory;

class LargeBlocksTest : public ::testing::Test {
protected:
    void SetUp() override { releaseKept(); }
    void TearDown() override { releaseKept(); }
};

TEST_F(LargeBlocksTest, ALargeBlockReleasedComesBackForASimilarSize)
{
    const std::size_t bytes = 3 * kRecycledBlockMinBytes;
    void* first = allocate(bytes);
    ASSERT_NE(first, nullptr);
    std::memset(first, 0xAB, bytes);
    release(first);
    void* second = allocate(bytes - 1000);
    EXPECT_EQ(second, first);
    release(second);
}

TEST_F(LargeBlocksTest, SmallBlocksAndMuchSmallerRequestsAreNotServedFromTheCache)
{
    void* small = allocate(1024);
    ASSERT_NE(small, nullptr);
    release(small); // freed at once: a later large request cannot get it
    const std::size_t bytes = 8 * kRecycledBlockMinBytes;
    void* large = allocate(bytes);
    ASSERT_NE(large, nullptr);
    release(large);
    // Less than half the kept block's size: a fresh block, the big one stays kept.
    void* quarter = allocate(bytes / 4);
    EXPECT_NE(quarter, large);
    void* again = allocate(bytes);
    EXPECT_EQ(again, large);
    release(quarter);
    release(again);
}

TEST_F(LargeBlocksTest, TheCacheKeepsAtMostItsCountOfBlocksTheNewestFirst)
{
    const std::size_t bytes = kRecycledBlockMinBytes + 4096;
    std::vector<void*> blocks;
    for (std::size_t i = 0; i < kRecycledBlockCount + 2; ++i)
        blocks.push_back(allocate(bytes));
    for (void* block : blocks)
        release(block);
    // The newest kRecycledBlockCount come back; the two oldest were freed.
    std::vector<void*> back;
    for (std::size_t i = 0; i < kRecycledBlockCount; ++i)
        back.push_back(allocate(bytes));
    for (std::size_t i = 2; i < blocks.size(); ++i)
        EXPECT_NE(std::find(back.begin(), back.end(), blocks[i]), back.end()) << i;
    for (void* block : back)
        release(block);
}

TEST_F(LargeBlocksTest, BlocksFromPlainMallocMayBeReleasedAndNullIsIgnored)
{
    release(nullptr);
    void* block = std::malloc(2 * kRecycledBlockMinBytes);
    ASSERT_NE(block, nullptr);
    release(block);
    EXPECT_EQ(allocate(2 * kRecycledBlockMinBytes), block);
    std::free(block); // and what allocate gives may go to free()
}

} // namespace
