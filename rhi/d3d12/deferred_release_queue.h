#pragma once
// Deferred destruction for the D3D12 backend, device-free (like Vulkan's VulkanContext::deferDestroy).
// D3D12 frees a resource the moment its last reference goes, even while the GPU still reads it; so an
// object's destructor hands its D3D12 objects here, tagged with the newest fence value submitted, and
// they are released once the queue's fence has completed that value. Example: a resize reallocates
// the caustic sphere TLAS and the filter history while the previous frames are still in flight.
#include <cstdint>
#include <functional>
#include <memory>
#include <mutex>
#include <vector>

namespace caustics::rhi::d3d12 {

class DeferredReleaseQueue {
public:
    // `completedFence` reads the fence value the GPU has completed (ID3D12Fence::GetCompletedValue).
    explicit DeferredReleaseQueue(std::function<uint64_t()> completedFence);
    DeferredReleaseQueue(const DeferredReleaseQueue&) = delete;
    DeferredReleaseQueue& operator=(const DeferredReleaseQueue&) = delete;
    ~DeferredReleaseQueue();

    // The device signalled `fence` after its latest submission (values only grow).
    void submitted(uint64_t fence);
    // Keeps `object` alive until everything submitted so far has completed; released at once when
    // nothing is in flight (or after shutdown()).
    void retire(std::shared_ptr<void> object);
    // Releases what the GPU has finished with. Called at every submit and wait.
    void collect();
    // The device is idle and going away: releases everything; later retire() calls release at once.
    void shutdown();

    size_t pendingCount() const;

private:
    struct Pending {
        uint64_t fence;
        std::shared_ptr<void> object;
    };
    std::function<uint64_t()> completedFence_;
    mutable std::mutex mutex_;
    uint64_t lastSubmitted_ = 0;
    bool shutDown_ = false;
    std::vector<Pending> pending_;
};

}  // namespace caustics::rhi::d3d12
