// SPDX-License-Identifier: MIT
// The loops of parallel_for.hpp without oneTBB (ENGINE_SERIAL_LOOPS: the web page's build, which
// has no WebAssembly oneTBB): every index once, in order, and chunks of the grain that cover the
// range exactly. Compiled here with the macro so that the native build checks the web's path.
#define ENGINE_SERIAL_LOOPS 1
#include <gtest/gtest.h>

#include <cstddef>
#include <utility>
#include <vector>

#include "engine/core/parallel_for.hpp"

TEST(SerialLoops, ParallelForVisitsEveryIndexOnceInOrder) {
    std::vector<int> seen;
    engine::parallelFor(3, 9, [&](int i) { seen.push_back(i); });
    EXPECT_EQ(seen, (std::vector<int>{3, 4, 5, 6, 7, 8}));
    seen.clear();
    engine::parallelFor(5, 5, [&](int i) { seen.push_back(i); });
    EXPECT_TRUE(seen.empty());
}

TEST(SerialLoops, ChunksOfTheGrainCoverTheRangeExactly) {
    std::vector<std::pair<std::size_t, std::size_t>> chunks;
    engine::parallelForChunks(std::size_t(2), std::size_t(13), std::size_t(4),
                              [&](std::size_t first, std::size_t last) { chunks.emplace_back(first, last); });
    using Chunk = std::pair<std::size_t, std::size_t>;
    EXPECT_EQ(chunks, (std::vector<Chunk>{{2, 6}, {6, 10}, {10, 13}}));
    chunks.clear();
    engine::parallelForChunks(std::size_t(0), std::size_t(3), std::size_t(0),
                              [&](std::size_t first, std::size_t last) { chunks.emplace_back(first, last); });
    EXPECT_EQ(chunks, (std::vector<Chunk>{{0, 1}, {1, 2}, {2, 3}}));
}
