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
// Smallest capacity: a frame that saw no sphere builds over this many inactive instances.
inline constexpr uint32_t kMinSphereCapacity = 64;

// No earlier count (first frame of a slot, or a different output size): every pixel can hold a
// sphere, so W x H is always enough.
uint32_t sphereTlasCapacity(std::optional<uint32_t> earlierCount, uint32_t pixels);

}  // namespace caustics
