// The debugger's checkpoints (ui/culler_checkpoints.h): saved on the interval,
// found at or before a frame, turned off by a culler that cannot be copied, and
// kept within their memory budget by dropping far ones first, so that the
// spacing near the current frame stays the interval.
#include "ui/culler_checkpoints.h"

#include <memory>
#include <vector>

#include <gtest/gtest.h>

namespace gridcull {
namespace {

// A culler whose state is `bytes` of heap, copied by clone() (or not copyable).
class BlobCuller final : public Culler {
public:
    BlobCuller(size_t bytes, bool copyable) : blob_(bytes, 1), copyable_(copyable) {}
    const char* name() const override { return "blob"; }
    void reset(const Scene&) override {}
    void cull(const Scene&, const Camera&, double, FrameResult& out) override { out.pvs.clear(); }
    std::unique_ptr<Culler> clone() const override {
        return copyable_ ? std::make_unique<BlobCuller>(*this) : nullptr;
    }

private:
    std::vector<char> blob_;
    bool copyable_;
};

constexpr size_t kMiB = size_t(1) << 20;

TEST(CullerCheckpoints, SavedOnTheIntervalAndFoundAtOrBefore) {
    CullerCheckpoints saved(64 * kMiB, 4);
    const BlobCuller culler(1024, true);
    for (int frame = 0; frame <= 13; ++frame) saved.offer(frame, culler);
    saved.offer(8, culler);       // again: already saved
    EXPECT_EQ(saved.count(), 4);  // 0, 4, 8, 12
    EXPECT_EQ(saved.latestAtOrBefore(11), 8);
    EXPECT_EQ(saved.latestAtOrBefore(12), 12);
    EXPECT_EQ(saved.latestAtOrBefore(0), 0);
    EXPECT_EQ(saved.latestAtOrBefore(-1), -1);
    EXPECT_NE(saved.restore(8), nullptr);
    EXPECT_EQ(saved.restore(9), nullptr);  // none saved there
    saved.dropAfter(5);
    EXPECT_EQ(saved.count(), 2);
    EXPECT_EQ(saved.latestAtOrBefore(11), 4);
}

TEST(CullerCheckpoints, ACullerThatCannotBeCopiedTurnsThemOff) {
    CullerCheckpoints saved;
    saved.offer(0, BlobCuller(16, false));
    EXPECT_FALSE(saved.enabled());
    EXPECT_EQ(saved.count(), 0);
    saved.offer(4, BlobCuller(16, true));
    EXPECT_EQ(saved.count(), 0);
    saved.clear();
    saved.offer(4, BlobCuller(16, true));
    EXPECT_EQ(saved.count(), 1);
}

TEST(CullerCheckpoints, OverBudgetTheFarOnesGoAndTheNearSpacingStays) {
    CullerCheckpoints saved(40 * kMiB, 4);
    const BlobCuller culler(kMiB, true);
    const int last = 400;
    saved.setFocus(last);
    for (int frame = 0; frame <= last; ++frame) saved.offer(frame, culler);
    if (saved.bytes() == 0) GTEST_SKIP() << "the heap is not glibc's (a sanitized build)";
    EXPECT_LE(saved.bytes(), saved.budget());
    EXPECT_LT(saved.count(), last / 4 + 1);
    EXPECT_EQ(saved.latestAtOrBefore(0), 0);
    // Near the focus, every interval is still there.
    for (int frame = last - kNearCheckpointFrames + 4; frame <= last; frame += 4)
        EXPECT_EQ(saved.latestAtOrBefore(frame), frame) << frame;
    // Far away the gaps widen, evenly: no gap more than twice another far one.
    EXPECT_GT(saved.widestGap(), 4);
    EXPECT_LE(saved.widestGap(), 2 * (last - kNearCheckpointFrames) / (saved.count() - 17));
}

}  // namespace
}  // namespace gridcull
