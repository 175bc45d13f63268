#pragma once
// How many sphere instances caustics.spheres builds its TLAS over (docs/caustics.md, "Second-type
// cost"). Neither D3D12 nor NVIDIA's Vulkan driver builds an acceleration structure from an instance
// count in GPU memory, so the CPU chooses the build's instance count: the larger of the sphere count and
// the specular pixel count of the last frame recorded in the same frame-in-flight slot (read back; the
// host has waited for that frame before executing this one, docs/embedding.md "Frames and views"), with
// headroom, rounded up to a bucket.
// Spheres past it are dropped and counted (kStatSpheresDropped, causticStatsWarnings); the count the GPU
// saw, dropped ones included, sizes the next frame of that slot.
//
// The memory follows the counts too (docs/caustics.md, "Memory"): the TLAS, the frame's sphere list and
// its instance buffer and the specular pixel list are allocated for initialSphereAllocation slots (from
// the specular surfaces in view), not W x H, and grow (never shrink) to the capacity a frame asked for
// past them, at the next graph built; spheres past the allocation meanwhile are dropped and counted like
// any other (causticStatsWarnings). A pixel's backward launch appends up to kMaxSpheresPerPixel spheres
// (its lobe branches, docs/caustics.md "Second-type lobes"); the specular pixel count is read back too:
// a list cut at the capacity still shows how much it should hold.
#include <cstdint>
#include <optional>

namespace caustics {

// Spheres one specular pixel's backward launch may append (shader::kBackwardMaxSpheres).
inline constexpr uint32_t kMaxSpheresPerPixel = 2;
// The most spheres a frame of `pixels` pixels can have: every capacity and allocation stays below it.
uint32_t sphereSlotLimit(uint32_t pixels);

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

// No earlier count (first frame of a slot, or a different output size): the slot limit
// (sphereSlotLimit), always enough.
uint32_t sphereTlasCapacity(std::optional<uint32_t> earlierCount, uint32_t slotLimit);

// The first allocation at an output size follows what the camera sees of the specular surfaces, not
// W x H: `specularCoverage` is the part of the image their bounding spheres' images cover (the sum of
// imageCoverage over the specular instances, caustics/caustic_importance.h), an upper bound of the
// specular pixels (a pixel is specular when its centre sees the object, inside that image; overlaps are
// counted twice), so kSpecularCoverageMargin is 1 (the lobe branches add a sphere on the pixels whose
// camera path meets a likely Fresnel reflection: a few percent to a quarter of them, which the
// bounding spheres' overestimate covers). The result is rounded up to the capacity's bucket, at least
// kMinSphereAllocation (2^15: test images up to 128x128 get two slots per pixel), at most
// sphereSlotLimit(W x H). A view whose specular pixels exceed it grows it within
// framesInFlight + 1 frames, dropping (and counting) the excess meanwhile, as for any jump of the count.
inline constexpr double kSpecularCoverageMargin = 1.0;
inline constexpr uint32_t kMinSphereAllocation = 1u << 15;
uint32_t initialSphereAllocation(uint32_t pixels, double specularCoverage);

// The allocation after a frame asked for `wanted` slots (a sphereTlasCapacity result past the
// allocation; 0 if none did): grow-only, so views of different sizes sharing it do not reallocate.
uint32_t grownSphereAllocation(uint32_t allocated, uint32_t wanted, uint32_t initial, uint32_t slotLimit);

}  // namespace caustics
