#pragma once
// Typed, versioned handles to graph resources (Frostbite FrameGraph, GDC 2017): every write returns
// a new version of the handle, so a read names exactly which producer it depends on and a stale
// handle (an older version) is rejected instead of silently reading the wrong data.
#include <cstdint>

namespace caustics::rg {

enum class ResourceKind : uint8_t { Texture, Buffer, AccelStruct };

inline constexpr uint32_t kInvalidIndex = ~0u;

template <ResourceKind K>
struct RgHandle {
    static constexpr ResourceKind kKind = K;
    uint32_t index = kInvalidIndex;   // resource slot in the graph
    uint32_t version = 0;             // 0 = contents at graph start; each write adds one

    bool valid() const { return index != kInvalidIndex; }
    friend bool operator==(const RgHandle&, const RgHandle&) = default;
};

using RgTexture = RgHandle<ResourceKind::Texture>;
using RgBuffer = RgHandle<ResourceKind::Buffer>;
using RgAccelStruct = RgHandle<ResourceKind::AccelStruct>;

const char* resourceKindName(ResourceKind kind);

}  // namespace caustics::rg
