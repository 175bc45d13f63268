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
#include <span>

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

// The part of the image the sphere's image covers, in [0, 1], exactly (the projected ellipse off the
// view axis, where viewCoverage's disk is smaller): an upper bound of the pixels an object inside the
// sphere covers, clamped at the image border as viewCoverage is.
float imageCoverage(const CausticView& view, glm::vec4 sphere);

// The part of the image the screen rectangle around a world box's projected corners covers, clipped to
// the image; 1 when a corner lies at or behind the eye. Also an upper bound of an object's pixels.
float imageCoverageOfBox(const CausticView& view, glm::vec3 lo, glm::vec3 hi);

// Per object the smaller of imageCoverage (its bounding sphere) and imageCoverageOfBox (its box, when
// `lo`/`hi` hold one), summed (overlaps counted twice) and clamped to 1: what a set of objects covers at
// most (the second type's first allocation, caustics/sphere_capacity.h).
double imageCoverageSum(const CausticView& view, std::span<const glm::vec4> spheres, std::span<const glm::vec3> lo = {},
                        std::span<const glm::vec3> hi = {});

}  // namespace caustics
