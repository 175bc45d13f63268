#pragma once
// CPU estimate of second-type caustics (paper 3.3: caustics seen through specular objects) that shares
// no formula with the GPU's gather: a dense first-type photon histogram of one horizontal receiver
// plane (renderCausticsReference seen straight down, without occlusion, so every caustic photon that
// lands on the plane is binned), read back along camera paths traced through the specular chain.
// The histogram holds the receiver's radiance towards +y (the top-down view), which is the radiance
// towards the camera path for the Lambertian receivers of the tests (BRDF independent of wo). The bins
// must be finer than the structure of interest; docs/physics.md "Second-type reference".
#include <cstdint>

#include <glm/glm.hpp>

#include "caustics/reference/reference_tracer.h"
#include "caustics/rhi/result.h"
#include "caustics/scene/scene.h"

namespace caustics::reference {

struct SecondTypeReferenceOptions {
    uint32_t width = 128;
    uint32_t height = 128;
    uint32_t samplesPerPixel = 64;        // jittered camera paths per pixel (the pixel's mean radiance)
    uint32_t maxDepth = 4;                // specular events per camera and photon path
    uint32_t seed = 0;
    uint32_t threads = 0;                 // 0 = hardware concurrency
    // Receiver: the plane y = receiverHeight (upper side), binned over the square |x - cx|, |z - cz| <=
    // receiverHalfSize around receiverCentre = (cx, cz) into histogramResolution^2 bins.
    float receiverHeight = 0.0f;
    glm::vec2 receiverCentre{0.0f};
    float receiverHalfSize = 0.5f;
    uint32_t histogramResolution = 512;
    uint64_t photonsPerLight = 16'000'000;
};

struct SecondTypeReference {
    ReferenceImage image;       // second-type radiance per pixel (receiver plane only), row 0 on top
    ReferenceImage histogram;   // receiver radiance per bin (row 0 at z = cz - halfSize)
    uint64_t pathsOnReceiver = 0;
};

Result<SecondTypeReference> renderSecondTypeReference(const scene::Scene& scene, const scene::Camera& camera,
                                                      const SecondTypeReferenceOptions& options);

}  // namespace caustics::reference
