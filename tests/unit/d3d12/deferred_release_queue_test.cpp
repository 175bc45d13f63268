// Deferred destruction on D3D12 (rhi/d3d12/deferred_release_queue.h): objects dropped while frames
// are in flight stay alive until the fence of the newest submission at the time they were dropped has
// completed. The fence is simulated; "alive" is observed through a weak_ptr or a COM reference count.
#include <utility>

#include <gtest/gtest.h>

#include "d3d12_objects.h"
#include "deferred_release_queue.h"

namespace caustics::rhi::d3d12 {
namespace {

class DeferredReleaseQueueTest : public ::testing::Test {
protected:
    uint64_t completed = 0;
    DeferredReleaseQueue queue{[this] { return completed; }};
};

TEST_F(DeferredReleaseQueueTest, ObjectDroppedWithNothingInFlightIsReleasedAtOnce) {
    auto object = std::make_shared<int>(1);
    std::weak_ptr<int> watch = object;
    queue.retire(std::move(object));
    EXPECT_TRUE(watch.expired());
    queue.submitted(1);
    completed = 1;
    object = std::make_shared<int>(2);
    watch = object;
    queue.retire(std::move(object));
    EXPECT_TRUE(watch.expired()) << "fence 1 already completed";
}

TEST_F(DeferredReleaseQueueTest, ObjectDroppedWhileFramesRunWaitsForTheNewestSubmission) {
    queue.submitted(1);
    queue.submitted(2);
    queue.submitted(3);
    completed = 1;
    auto object = std::make_shared<int>(7);
    std::weak_ptr<int> watch = object;
    queue.retire(std::move(object));
    queue.collect();
    EXPECT_FALSE(watch.expired()) << "frames 2 and 3 may still read it";
    completed = 2;
    queue.collect();
    EXPECT_FALSE(watch.expired());
    completed = 3;
    queue.collect();
    EXPECT_TRUE(watch.expired());
    EXPECT_EQ(queue.pendingCount(), 0u);
}

// CausticResources::ensureSizeResources on a resize: the sphere TLAS and the filter history of the
// old size are replaced while the two previous frames are still in flight.
TEST_F(DeferredReleaseQueueTest, ResizeDuringFramesInFlightKeepsOldTlasAndHistoryUntilTheirFramesFinish) {
    auto tlas = std::make_shared<int>(0), history = std::make_shared<int>(0);
    std::weak_ptr<int> oldTlas = tlas, oldHistory = history;
    queue.submitted(10);   // frame N-1 uses them
    queue.submitted(11);   // frame N uses them
    completed = 9;
    queue.retire(std::exchange(tlas, std::make_shared<int>(1)));   // resize before frame N+1
    queue.retire(std::exchange(history, std::make_shared<int>(1)));
    queue.submitted(12);   // frame N+1 uses the new ones
    EXPECT_EQ(queue.pendingCount(), 2u);
    completed = 10;
    queue.collect();
    EXPECT_FALSE(oldTlas.expired());
    EXPECT_FALSE(oldHistory.expired());
    completed = 11;
    queue.collect();
    EXPECT_TRUE(oldTlas.expired());
    EXPECT_TRUE(oldHistory.expired());
    EXPECT_EQ(*tlas, 1) << "the new TLAS is untouched";
}

TEST_F(DeferredReleaseQueueTest, EachObjectWaitsOnlyForTheSubmissionsBeforeItWasDropped) {
    queue.submitted(1);
    auto first = std::make_shared<int>(1);
    std::weak_ptr<int> watchFirst = first;
    queue.retire(std::move(first));
    queue.submitted(2);
    auto second = std::make_shared<int>(2);
    std::weak_ptr<int> watchSecond = second;
    queue.retire(std::move(second));
    completed = 1;
    queue.collect();
    EXPECT_TRUE(watchFirst.expired());
    EXPECT_FALSE(watchSecond.expired());
}

TEST_F(DeferredReleaseQueueTest, ShutdownReleasesEverythingAndLaterDropsAreImmediate) {
    queue.submitted(5);
    auto object = std::make_shared<int>(1);
    std::weak_ptr<int> watch = object;
    queue.retire(std::move(object));
    queue.shutdown();   // the device waited idle
    EXPECT_TRUE(watch.expired());
    object = std::make_shared<int>(2);
    watch = object;
    queue.retire(std::move(object));   // an object outliving its device
    EXPECT_TRUE(watch.expired());
}

// A COM object as the backend holds them: the reference drops only when its fence completes.
class CountingUnknown final : public IUnknown {
public:
    explicit CountingUnknown(int& released) : released_(released) {}
    HRESULT STDMETHODCALLTYPE QueryInterface(REFIID, void**) override { return E_NOINTERFACE; }
    ULONG STDMETHODCALLTYPE AddRef() override { return ++refs_; }
    ULONG STDMETHODCALLTYPE Release() override {
        if (--refs_ == 0) {
            ++released_;
            delete this;
            return 0;
        }
        return refs_;
    }

private:
    int& released_;
    ULONG refs_ = 1;
};

TEST_F(DeferredReleaseQueueTest, RetiredComReferencesAreReleasedAfterTheirFence) {
    auto releases = std::make_shared<DeferredReleaseQueue>([this] { return completed; });
    int released = 0;
    ComPtr<IUnknown> resource, scratch, none;
    *resource.put() = new CountingUnknown(released);
    *scratch.put() = new CountingUnknown(released);
    releases->submitted(4);
    retireToQueue(releases, resource, scratch, none);
    EXPECT_FALSE(resource) << "the object no longer holds it";
    EXPECT_EQ(released, 0);
    EXPECT_EQ(releases->pendingCount(), 2u) << "an empty ComPtr is not queued";
    completed = 4;
    releases->collect();
    EXPECT_EQ(released, 2);
}

}  // namespace
}  // namespace caustics::rhi::d3d12
