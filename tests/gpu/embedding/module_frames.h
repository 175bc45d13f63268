#pragma once
// Runs CausticsModule frames the way an engine does: one render graph and one command list per
// frame-in-flight slot, frame n waits only for frame n - framesInFlight, and every frame's chosen
// output image is copied (inside that frame's graph) into its own readback buffer. Shared by the
// embedding tests (live scene, views, frames in flight, projections).
#include <cstdint>
#include <functional>
#include <vector>

#include <glm/glm.hpp>

#include "caustics/caustics_module.h"

namespace caustics::test {

enum class ModuleOutput { Caustics, FirstType, SecondType };

struct FrameImage {
    uint32_t width = 0, height = 0;
    std::vector<glm::vec3> pixels;   // row 0 = top; linear cd/m^2
};

// One view of one frame: its inputs (frameIndex is set by runModuleFrames) and which output to read.
struct ViewRequest {
    FrameInputs inputs;
    ModuleOutput output = ModuleOutput::Caustics;
};

// A square view of `camera` with a standard projection.
ViewRequest viewOf(const scene::Camera& camera, uint32_t size, ModuleOutput output = ModuleOutput::Caustics,
                   CausticsView* view = nullptr);

// InTurn: frame n is built, then executed, then frame n + 1 built. BuildAhead: a render thread ahead of
// the GPU, frame n + 1 is built before frame n executes (docs/embedding.md "Frames and views").
enum class FrameOrder { InTurn, BuildAhead };

// Calls `frameViews(n)` for n = 0..frames-1 (it may change the module's scene first) and adds every
// returned view to frame n's graph; returns images[n][view]. framesInFlight graphs rotate.
Result<std::vector<std::vector<FrameImage>>> runModuleFrames(
    rhi::IDevice& device, CausticsModule& module, uint32_t frames, uint32_t framesInFlight,
    const std::function<std::vector<ViewRequest>(uint32_t frame)>& frameViews, FrameOrder order = FrameOrder::InTurn);

float luminance(const glm::vec3& v);

// sum |a - b| / sum |b| of luminance over all pixels (0 for identical images).
double relativeL1(const FrameImage& a, const FrameImage& b);
double totalLuminance(const FrameImage& img);

// Luminance-weighted centroid of the pixels at or above `fraction` of the brightest pixel's
// luminance after a 3x3 box blur (robust to single-pixel noise): the caustic's peak position.
glm::vec2 peakCentroid(const std::vector<glm::vec3>& pixels, uint32_t width, uint32_t height, float fraction = 0.5f);

}  // namespace caustics::test
