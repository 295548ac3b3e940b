#include "grid/id_list_matrix.h"

#include <algorithm>
#include <map>
#include <set>
#include <vector>

#include <gtest/gtest.h>

#include "culling/scene/seeded_random.h"

namespace gridcull {
namespace {

std::vector<int32_t> listOf(const IdListMatrix& m, int x, int y) {
    std::vector<int32_t> ids;
    m.forEach(x, y, [&](int32_t id) { ids.push_back(id); });
    std::sort(ids.begin(), ids.end());
    return ids;
}

TEST(IdListMatrix, NoMemoryUntilTheFirstAdd) {
    IdListMatrix m;
    m.resize(1024, 1024, false);
    EXPECT_EQ(m.memoryBytes(), size_t(0));
    EXPECT_TRUE(m.empty(5, 5));
    m.add(5, 5, 7);
    EXPECT_GE(m.memoryBytes(), size_t(1024) * 1024 * 4);
    EXPECT_EQ(listOf(m, 5, 5), std::vector<int32_t>{7});
}

TEST(IdListMatrix, ResizeToTheSameShapeEmptiesAndKeepsStorage) {
    IdListMatrix m;
    m.resize(64, 32, false, 2, true);
    for (int k = 0; k < 500; ++k) m.addNode(k % 64, k % 32, k);
    const size_t grown = m.memoryBytes();
    m.resize(64, 32, false, 2, true);
    EXPECT_EQ(m.idCount(), 0);
    EXPECT_TRUE(m.empty(3, 3));
    EXPECT_EQ(m.memoryBytes(), grown);  // kept, for a culler reset on the same scene
    m.resize(64, 16, false, 2, true);   // another shape: freed
    EXPECT_EQ(m.memoryBytes(), size_t(0));
    m.addNode(1, 1, 9);
    m.release();
    m.resize(64, 16, false, 2, true);  // released first: nothing kept
    EXPECT_EQ(m.memoryBytes(), size_t(0));
}

TEST(IdListMatrix, AddRemoveMatchesAReferenceMap) {
    SeededRandom rng(11);
    IdListMatrix m;
    m.resize(9, 7, false);
    std::map<std::pair<int, int>, std::multiset<int32_t>> ref;
    for (int step = 0; step < 20000; ++step) {
        const int x = int(rng.below(9)), y = int(rng.below(7));
        const int32_t id = int32_t(rng.below(6));
        auto& cell = ref[{x, y}];
        if (rng.uniform() < 0.55) {
            m.add(x, y, id);
            cell.insert(id);
        } else {
            const bool had = cell.count(id) > 0;
            EXPECT_EQ(m.remove(x, y, id), had);
            if (had) cell.erase(cell.find(id));
        }
    }
    int64_t ids = 0, non_empty = 0;
    for (int y = 0; y < 7; ++y) {
        for (int x = 0; x < 9; ++x) {
            const auto& cell = ref[{x, y}];
            EXPECT_EQ(listOf(m, x, y), std::vector<int32_t>(cell.begin(), cell.end()));
            EXPECT_EQ(m.listLength(x, y), int(cell.size()));
            EXPECT_EQ(m.empty(x, y), cell.empty());
            ids += int64_t(cell.size());
            non_empty += cell.empty() ? 0 : 1;
        }
    }
    EXPECT_EQ(m.idCount(), ids);
    EXPECT_EQ(m.nonEmptyVoxels(), non_empty);
}

TEST(IdListMatrix, SteadyAddAndRemoveReusesNodes) {
    IdListMatrix m;
    m.resize(64, 64, false);
    for (int frame = 0; frame < 3; ++frame)
        for (int i = 0; i < 64; ++i) m.add(i, i, i);
    for (int i = 0; i < 64; ++i) m.remove(i, i, i);
    const size_t bytes = m.memoryBytes();
    for (int frame = 0; frame < 50; ++frame) {
        for (int i = 0; i < 64; ++i) m.add(i, 63 - i, frame);
        for (int i = 0; i < 64; ++i) EXPECT_TRUE(m.remove(i, 63 - i, frame));
    }
    EXPECT_EQ(m.memoryBytes(), bytes);  // the free list served every add
}

TEST(IdListMatrix, ClearTouchedEmptiesOnlyWhatWasWritten) {
    IdListMatrix m;
    m.resize(32, 32, true);
    for (int frame = 0; frame < 5; ++frame) {
        for (int i = 0; i < 32; ++i) {
            m.add(i, (i * 7 + frame) % 32, i);
            m.add(i, (i * 7 + frame) % 32, i + 100);
        }
        EXPECT_EQ(m.idCount(), 64);
        EXPECT_EQ(m.nonEmptyVoxels(), 32);
        m.clear();
        EXPECT_EQ(m.idCount(), 0);
        EXPECT_EQ(m.nonEmptyVoxels(), 0);
        for (int y = 0; y < 32; ++y)
            for (int x = 0; x < 32; ++x) ASSERT_TRUE(m.empty(x, y));
    }
}

}  // namespace
}  // namespace gridcull
