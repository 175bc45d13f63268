#pragma once
// Placement of transient resources in one heap: resources whose lifetimes overlap get disjoint byte
// ranges; others may share memory. Greedy first-fit over offsets, largest first (the usual interval
// packing of frame graphs; optimal packing is NP-hard, this is within a small factor in practice).
#include <cstdint>
#include <vector>

#include "caustics/render_graph/compiled_plan.h"

namespace caustics::rg {

struct AliasRequest {
    uint64_t size = 0;
    uint64_t alignment = 1;
    Lifetime lifetime;
};

struct AliasPlacement {
    std::vector<uint64_t> offsets;   // one per request, aligned to its alignment
    uint64_t heapSize = 0;
};

AliasPlacement placeAliased(const std::vector<AliasRequest>& requests);

}  // namespace caustics::rg
