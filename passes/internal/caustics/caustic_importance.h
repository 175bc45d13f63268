#pragma once
// How much of a cluster's caustic the camera can see (docs/caustics.md, "Photon budget"): the weight by
// which the photon budget is split over map layers, and zero for a layer whose caustic cannot reach the
// view, which then gets no map at all.
//
// A cluster's caustic lands on receivers near it: within receiverReach cluster radii of the cluster's
// bounding sphere (CausticsSettings::causticReceiverReach; a glass ball's focal spot lies about one
// radius behind it, a window's patch on the floor a few window sizes away). The weight is the part of
// the image that sphere of receivers covers: photons are spent per covered pixel, so every visible
// caustic gets about the same photons per pixel, whatever its distance and the level's extent.
#include <cstdint>

#include <glm/glm.hpp>

#include "caustics/camera_constants.h"

namespace caustics {

struct CausticView {
    glm::mat4 viewProj{1.0f};
    glm::vec3 eye{0.0f};
    glm::vec3 forward{0.0f, 0.0f, -1.0f};
    float tanHalfFovY = 1.0f;
    uint32_t width = 1, height = 1;
};
CausticView causticViewOf(const CameraConstants& camera);

// The sphere of a cluster's possible receivers: same centre, radius x (1 + reach).
glm::vec4 causticReceiverSphere(glm::vec4 cluster, float reach);

// Fraction of the image the sphere covers, in [0, 1]: 0 when it lies outside the view frustum's side
// planes or behind the eye, 1 with the eye inside it; else its projected disk's area over the image's,
// clamped to 1 (conservative at the image border, where part of the disk is off screen).
float viewCoverage(const CausticView& view, glm::vec4 sphere);

}  // namespace caustics
