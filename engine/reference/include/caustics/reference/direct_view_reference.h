#pragma once
// CPU reference of the direct-lighting view (what the GPU direct-lighting pass renders): a ray through
// each pixel centre; at every surface the direct light of all scene lights with ray-cast shadows and
// the glTF BRDF of shaders/common/bsdf.h; at smooth specular surfaces both lobes of
// shaders/common/view_lobes.h are followed to `maxSpecularEvents`, with no split limit (the GPU pass
// splits only its first events), so it converges to the full two-lobe answer the GPU approximates.
#include <cstdint>

#include "caustics/reference/reference_tracer.h"

namespace caustics::reference {

struct DirectViewOptions {
    uint32_t width = 256;
    uint32_t height = 256;
    uint32_t maxSpecularEvents = 10;   // per camera path
    float minBranchWeight = 1.0e-4f;   // branches whose throughput falls below are dropped
    uint32_t threads = 0;              // 0 = std::thread::hardware_concurrency()
};

// Linear radiance (cd/m^2 for KHR_lights_punctual units), row 0 at the top; photon counts stay 0.
Result<ReferenceImage> renderDirectViewReference(const scene::Scene& scene, const scene::Camera& camera,
                                                 const DirectViewOptions& options);

}  // namespace caustics::reference
