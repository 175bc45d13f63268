#pragma once
// CPU reference light tracer: traces photons from every light of a scene::Scene through specular
// chains with the BSDF, emission and splatting code of shaders/common (compiled as C++), and splats
// each diffuse hit into a radiance image with the light-tracing estimator (docs/physics.md).
// Deterministic for a fixed seed and thread count.
#include <cstdint>
#include <vector>

#include <glm/glm.hpp>

#include "caustics/rhi/result.h"
#include "caustics/scene/scene.h"

namespace caustics::reference {

enum class ReferenceMode : uint8_t {
    CausticsOnly,  // light -> specular+ -> diffuse -> camera (the paper's first type)
    AllLightPaths, // every diffuse hit, with diffuse bounces continued (light tracing)
};

struct ReferenceOptions {
    uint32_t width = 256;
    uint32_t height = 256;
    uint64_t photonsPerLight = 1'000'000;  // rounded to whole emission-map texels
    uint32_t maxDepth = 4;                 // specular events per path (and diffuse bounces)
    uint32_t seed = 0;                     // the "frame" key of the shared RNG
    uint32_t threads = 0;                  // 0 = std::thread::hardware_concurrency()
    ReferenceMode mode = ReferenceMode::CausticsOnly;
    bool russianRoulette = false;          // after the 2nd event, survival = min(1, max throughput)
    bool visibilityTest = true;            // cast a ray from each splat to the eye
};

// Linear radiance image, cd/m^2 per channel when light intensities are in KHR_lights_punctual units.
// Row 0 is the top of the image.
struct ReferenceImage {
    uint32_t width = 0;
    uint32_t height = 0;
    std::vector<glm::vec3> pixels;
    uint64_t photonsEmitted = 0;
    uint64_t photonsSplatted = 0;

    const glm::vec3& at(uint32_t x, uint32_t y) const { return pixels[size_t(y) * width + x]; }
};

Result<ReferenceImage> renderCausticsReference(const scene::Scene& scene, const scene::Camera& camera,
                                               const ReferenceOptions& options);

}  // namespace caustics::reference
