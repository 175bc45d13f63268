#include "deferred_release_queue.h"

#include <algorithm>

namespace caustics::rhi::d3d12 {

DeferredReleaseQueue::DeferredReleaseQueue(std::function<uint64_t()> completedFence)
    : completedFence_(std::move(completedFence)) {}

DeferredReleaseQueue::~DeferredReleaseQueue() { shutdown(); }

void DeferredReleaseQueue::submitted(uint64_t fence) {
    std::lock_guard lock(mutex_);
    lastSubmitted_ = std::max(lastSubmitted_, fence);
}

void DeferredReleaseQueue::retire(std::shared_ptr<void> object) {
    if (!object) return;
    std::unique_lock lock(mutex_);
    const uint64_t fence = lastSubmitted_;
    if (shutDown_ || fence == 0 || completedFence_() >= fence) {
        lock.unlock();
        object.reset();   // outside the lock: a release may retire further objects
        return;
    }
    pending_.push_back({fence, std::move(object)});
}

void DeferredReleaseQueue::collect() {
    std::vector<Pending> ready;
    {
        std::lock_guard lock(mutex_);
        if (pending_.empty()) return;
        const uint64_t done = completedFence_();
        auto firstPending = std::stable_partition(pending_.begin(), pending_.end(),
                                                  [&](const Pending& p) { return p.fence <= done; });
        ready.assign(std::make_move_iterator(pending_.begin()), std::make_move_iterator(firstPending));
        pending_.erase(pending_.begin(), firstPending);
    }
    ready.clear();   // released outside the lock
}

void DeferredReleaseQueue::shutdown() {
    std::vector<Pending> all;
    {
        std::lock_guard lock(mutex_);
        shutDown_ = true;
        all.swap(pending_);
    }
    all.clear();
}

size_t DeferredReleaseQueue::pendingCount() const {
    std::lock_guard lock(mutex_);
    return pending_.size();
}

}  // namespace caustics::rhi::d3d12
