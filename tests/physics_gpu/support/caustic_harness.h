#pragma once
// Runs one or more frames of the G-buffer pass and the caustic passes (caustic_passes.h) for a scene
// and reads the results back: radiance images, statistics, stored hits and spheres.
#include <cstdint>
#include <span>
#include <vector>

#include <glm/glm.hpp>

#include "caustics/caustic_passes.h"
#include "caustics/rhi/rhi.h"
#include "caustics/scene/scene.h"

namespace caustics::test {

struct CausticRun {
    uint32_t width = 0, height = 0;
    std::vector<glm::vec3> firstType, secondType, radiance;   // row 0 = top
    std::vector<uint32_t> stats;                             // kStatCount words
    std::vector<CausticHit> hits;                            // min(attempts, maxStoredHits)
    std::vector<CausticSphere> spheres;                      // the frame's spheres, in append order (secondType on)
    std::vector<float> linearDepth;
    // The second type's own guides (CausticOutputs::secondTypeGuides; empty without the second type):
    // receiver depth, motion x, motion y, 0 / receiver normal / receiver object id.
    std::vector<glm::vec4> guideDepthMotion, guideNormal;
    std::vector<uint32_t> guideObjectId;
    std::vector<uint32_t> objectId;
    uint32_t filterTiles = ~0u;                              // tiles the filter ran on (settings.filter)
    bool secondTypeListOrder = false;                        // CausticOutputs::secondTypeListOrder (read back
                                                             // into the screen images above)
    CausticMapPlan plan;
    std::vector<CausticLayerPlanGpu> layerPlans;             // one per plan.maps entry

    uint32_t raysOfLight(uint32_t light) const { return stats[kStatRaysPerLight + light]; }
    const glm::vec3& at(const std::vector<glm::vec3>& img, uint32_t x, uint32_t y) const { return img[size_t(y) * width + x]; }
};

// frames > 1 runs the graph repeatedly (frame index 0..frames-1) and returns the last frame.
// separateTypes (CausticFrameInputs::separateTypes): the types' own textures, as for an AOV; false runs
// what a host without an AOV gets (with the second type filtered apart: the second type in list order,
// common/specular_list.h, read back into screen images here), and leaves firstType empty.
Result<CausticRun> runCaustics(rhi::IDevice& device, const scene::Scene& scene, const scene::Camera& camera,
                               uint32_t width, uint32_t height, const CausticsSettings& settings, uint32_t frames = 1,
                               bool separateTypes = true);
// One frame per camera (a moving view; each frame's prevViewProj is the camera before it), on
// CausticResources made for `framesInFlight` frame slots (frame n reuses slot n % framesInFlight).
// With `lightsPerFrame` (one light list per camera), frame n renders the scene with those lights
// (moving lights: the caustic moves under a still camera).
Result<CausticRun> runCaustics(rhi::IDevice& device, const scene::Scene& scene, std::span<const scene::Camera> cameras,
                               uint32_t width, uint32_t height, const CausticsSettings& settings,
                               uint32_t framesInFlight = 3,
                               std::span<const std::vector<scene::Light>> lightsPerFrame = {}, bool separateTypes = true);

// Sum of `images` over several independent frames (different seeds) divided by their count.
}  // namespace caustics::test
