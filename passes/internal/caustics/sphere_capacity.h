#pragma once
// How many sphere instances caustics.spheres builds its TLAS over (docs/caustics.md, "Second-type
// cost"). Neither D3D12 nor NVIDIA's Vulkan driver builds an acceleration structure from an instance
// count in GPU memory, so the CPU chooses the build's instance count: the sphere count of the last
// frame recorded in the same frame-in-flight slot (read back; the host has waited for that frame before
// executing this one, docs/embedding.md "Frames and views"), with headroom, rounded up to a bucket.
// Spheres past it are dropped and counted (kStatSpheresDropped, causticStatsWarnings); the count the GPU
// saw, dropped ones included, sizes the next frame of that slot.
//
// The memory follows the counts too (docs/caustics.md, "Memory"): the TLAS, the frame's sphere list and
// its instance buffer are allocated for initialSphereAllocation(W x H) slots, not W x H, and grow (never
// shrink) to the capacity a frame asked for past them, at the next graph built; spheres past the
// allocation meanwhile are dropped and counted like any other (causticStatsWarnings).
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

// The first allocation at an output size: a sixteenth of the pixels (a view whose specular surfaces
// cover more grows it within framesInFlight + 1 frames), at least kMinSphereAllocation (2^17: small
// images, such as the tests' and the sample's memory fit at 320x240, get a slot for every pixel; at
// 1080p it is the sixteenth's 129,600 rounded up), at most W x H.
inline constexpr uint32_t kInitialSphereFractionDivisor = 16;
inline constexpr uint32_t kMinSphereAllocation = 1u << 17;
uint32_t initialSphereAllocation(uint32_t pixels);

// The allocation after a frame asked for `wanted` slots (a sphereTlasCapacity result past the
// allocation; 0 if none did): grow-only, so views of different sizes sharing it do not reallocate.
uint32_t grownSphereAllocation(uint32_t allocated, uint32_t wanted, uint32_t pixels);

}  // namespace caustics
