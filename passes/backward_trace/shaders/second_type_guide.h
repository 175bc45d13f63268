#ifndef CAUSTICS_PASS_SECOND_TYPE_GUIDE_H
#define CAUSTICS_PASS_SECOND_TYPE_GUIDE_H
// One pixel's second-type filter guide, in the shared dialect (docs/shaders.md; docs/caustics.md
// "Second-type guides"): the receiver a backward path reached through the glass (its depth, motion, normal,
// object id and photon weight), or, where that receiver is no surface the filter can follow from pixel to
// pixel, the glass the camera sees. Written by caustics.secondTypeGuides (second_type_guides.h) and
// completed by caustics.secondTypeGuides.fill and .glass (second_type_guide_fill.h).
#include "common/camera.h"
#include "common/caustic_hit.h"
#include "common/luminance.h"

CAUSTICS_SHARED_BEGIN
// Motion of a receiver point that was behind last frame's camera: far off screen, so no history is found
// (within half precision's range: the guide is stored as half).
CAUSTICS_CONST float kGuideNoHistory = -6.0e4f;
// A receiver reached by a reflection can lie behind the camera (clip w <= 0): the filter divides by
// depths, so the guide holds |w|, at least this (metres).
CAUSTICS_CONST float kGuideMinDepth = 1.0e-3f;

struct SecondTypeGuide {
    float linearDepth;   // |clip w| of the receiver point, at least kGuideMinDepth
    float2 motion;       // last frame's texel-centre position minus this frame's, pixels
    float previousDepth; // clip w last frame (0: behind last frame's camera, no history)
    float3 normal;
    uint objectId;
    float photonWeight;  // luminance one photon of unit flux and BRDF adds here, per unfolded pixel (below)
};

// A world point in clip space through `viewProj` (the camera's or last frame's).
CAUSTICS_FN float4 guideClip(float4x4 viewProj, float3 x) { return mat4Mul(viewProj, float4(x, 1.0f)); }

// Texel-centre coordinates of a clip-space point (pixel (i, j)'s centre is (i, j)), as the filter's
// reprojection computes them (docs/caustics.md "Filter").
CAUSTICS_FN float2 guideTexel(float4 clip, float2 size) {
    return (float2(clip.x, clip.y) / clip.w * 0.5f + 0.5f) * size - 0.5f;
}

// The luminance a gathered photon adds to the sphere's pixel is transmittance x flux x BRDF / (pi r^2)
// (docs/physics.md "Second-type density estimate"): through a curved glass the disk's area changes from
// pixel to pixel, and with it the size of one photon's step. The filter's shot-noise variance for a
// young history needs that step at each pixel (caustics.variance, varianceShotNoise); the guide carries
// its geometric part, lum(transmittance) / (pi r^2), times the unfolded pixel's area at the receiver's
// depth (depth^2 x pixel solid angle), which keeps it near 1 / magnification^2 in half precision.
CAUSTICS_FN float secondTypePhotonWeight(CameraConstants c, CausticSphere s, float linearDepth) {
    float unfoldedArea = linearDepth * linearDepth * pinholePixelArea(cameraPinhole(c));
    return rec709Luminance(s.transmittance) * unfoldedArea / max(kPi * s.radius * s.radius, 1.0e-30f);
}

CAUSTICS_FN SecondTypeGuide secondTypeGuide(CameraConstants c, CausticSphere s, float2 size) {
    float4 now = guideClip(c.viewProj, s.centre);
    float4 before = guideClip(c.prevViewProj, s.centre);
    SecondTypeGuide g;
    g.linearDepth = max(abs(now.w), kGuideMinDepth);
    bool seen = before.w > 0.0f && now.w > 0.0f;
    g.motion = seen ? guideTexel(before, size) - guideTexel(now, size) : splat2(kGuideNoHistory);
    g.previousDepth = seen ? before.w : 0.0f;
    g.normal = s.normal;
    g.objectId = s.objectId;
    g.photonWeight = min(secondTypePhotonWeight(c, s, g.linearDepth), 65504.0f);   // half's largest
    return g;
}

// The glass's own guide motion (docs/caustics.md "Second-type guides", incoherent receivers): the
// glass point the camera sees at the pixel now (glassNow) and where it was last frame (glassBefore, the
// same point unless the glass moved), as the filter's first-type run reprojects a surface seen directly.
// xy: last frame's texel-centre position minus this frame's (kGuideNoHistory when either was behind its
// camera), z: last frame's clip w (0 then).
CAUSTICS_FN float3 glassGuideMotion(CameraConstants c, float3 glassNow, float3 glassBefore, float2 size) {
    float4 now = guideClip(c.viewProj, glassNow);
    float4 before = guideClip(c.prevViewProj, glassBefore);
    bool seen = before.w > 0.0f && now.w > 0.0f;
    float2 motion = seen ? guideTexel(before, size) - guideTexel(now, size) : splat2(kGuideNoHistory);
    return float3(motion.x, motion.y, seen ? before.w : 0.0f);
}
// A receiver seen through a glass that moved (docs/caustics.md "Moving objects"): what the glass shows
// moves with it, the lens and the caustic under it alike, so the guide's motion is the glass point's
// (glassNow at this pixel, glassBefore where it was last frame, both world) and last frame's depth is
// the receiver point's carried by the glass's motion (receiverBefore).
CAUSTICS_FN SecondTypeGuide secondTypeGuideThroughMovedGlass(CameraConstants c, SecondTypeGuide g, float3 glassNow,
                                                             float3 glassBefore, float3 receiverBefore, float2 size) {
    float3 glass = glassGuideMotion(c, glassNow, glassBefore, size);
    float4 receiver = guideClip(c.prevViewProj, receiverBefore);
    bool seen = glass.z > 0.0f && receiver.w > 0.0f;
    SecondTypeGuide r = g;
    r.motion = seen ? float2(glass.x, glass.y) : splat2(kGuideNoHistory);
    r.previousDepth = seen ? receiver.w : 0.0f;
    return r;
}
CAUSTICS_SHARED_END

#endif  // CAUSTICS_PASS_SECOND_TYPE_GUIDE_H
