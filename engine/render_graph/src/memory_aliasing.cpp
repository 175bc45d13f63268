#include "caustics/render_graph/memory_aliasing.h"

#include <algorithm>
#include <numeric>

namespace caustics::rg {
namespace {
uint64_t alignUp(uint64_t value, uint64_t alignment) {
    return alignment <= 1 ? value : (value + alignment - 1) / alignment * alignment;
}
}  // namespace

AliasPlacement placeAliased(const std::vector<AliasRequest>& requests) {
    AliasPlacement result;
    result.offsets.assign(requests.size(), 0);
    // Largest first: big resources claim the low offsets, small ones fill the gaps between them.
    std::vector<size_t> order(requests.size());
    std::iota(order.begin(), order.end(), size_t{0});
    std::stable_sort(order.begin(), order.end(), [&](size_t a, size_t b) {
        if (requests[a].size != requests[b].size) return requests[a].size > requests[b].size;
        return requests[a].lifetime.first < requests[b].lifetime.first;
    });

    struct Range { uint64_t begin, end; };
    std::vector<size_t> placed;
    for (size_t i : order) {
        const AliasRequest& req = requests[i];
        std::vector<Range> busy;   // ranges of placed resources alive at the same time
        for (size_t j : placed)
            if (requests[j].lifetime.overlaps(req.lifetime))
                busy.push_back({result.offsets[j], result.offsets[j] + requests[j].size});
        std::sort(busy.begin(), busy.end(), [](const Range& a, const Range& b) { return a.begin < b.begin; });
        uint64_t offset = 0;
        for (const Range& r : busy) {
            offset = alignUp(offset, req.alignment);
            if (offset + req.size <= r.begin) break;   // fits in the gap before r
            offset = std::max(offset, r.end);
        }
        offset = alignUp(offset, req.alignment);
        result.offsets[i] = offset;
        result.heapSize = std::max(result.heapSize, offset + req.size);
        placed.push_back(i);
    }
    return result;
}

}  // namespace caustics::rg
