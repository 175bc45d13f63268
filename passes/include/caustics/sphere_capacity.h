#pragma once
// How many sphere instances caustics.spheres builds its TLAS over (docs/caustics.md, "Second-type
// cost"). Neither D3D12 nor NVIDIA's Vulkan driver builds an acceleration structure from an instance
// count in GPU memory, so the CPU chooses the build's instance count: the sphere count of the last
// frame recorded in the same frame-in-flight slot (read back; the host has waited for that frame before
// executing this one, docs/embedding.md "Frames and views"), with headroom, rounded up to a bucket.
// Spheres past it are dropped and counted (kStatSpheresDropped, causticStatsWarnings); the count the GPU
// saw, dropped ones included, sizes the next frame of that slot. The TLAS itself stays allocated for
// W x H instances, so any capacity fits without reallocation.
#include <cstdint>
#include <optional>

namespace caustics {

// Headroom over the earlier count (x 1.25) absorbs frame-to-frame change in the specular pixels seen;
// the bucket (an eighth of the next power of two, so 1.25-1.4 x in all) keeps the capacity, and so
// the build's cost, steady while the count wobbles.
inline constexpr double kSphereCapacityHeadroom = 1.25;
// Smallest capacity when the earlier frame had spheres.
inline constexpr uint32_t kMinSphereCapacity = 64;
// After a frame without spheres (the camera turned away from every specular object) the capacity is 0:
// caustics.spheres builds nothing and caustics.gather launches nothing, so such frames cost ~0 there
// (a TLAS build has a fixed cost: 0.05 ms for 64 inactive instances on the H200). The price: when
// specular objects come into view, their spheres are dropped (and counted) for up to framesInFlight
// frames, as for any jump of the count.

// No earlier count (first frame of a slot, or a different output size): every pixel can hold a
// sphere, so W x H is always enough.
uint32_t sphereTlasCapacity(std::optional<uint32_t> earlierCount, uint32_t pixels);

}  // namespace caustics
