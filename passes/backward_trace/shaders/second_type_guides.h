#ifndef CAUSTICS_PASS_SECOND_TYPE_GUIDES_H
#define CAUSTICS_PASS_SECOND_TYPE_GUIDES_H
// The second type's own filter guides, in the shared dialect (docs/shaders.md; docs/caustics.md
// "Second-type guides"): a pixel whose camera path went through glass shows a caustic that lies on the
// receiver the path reached, not on the glass the G-buffer holds. So the receiver's linear depth (clip w),
// its normal (facing the arriving path), its object id and its screen motion (where the receiver point
// was last frame minus where it is now, pixels) are written at the pixel from that pixel's likely-path
// sphere (caustics.backward: at most one per pixel; a lobe branch's sphere is never likely). The pixel's
// object id goes to sphereObjectId (the clear pass zeroes it: id 0, no receiver), its other guides to
// depthMotion and normal, which the fill (second_type_guide_fill.h) completes in place: it writes every
// pixel whose sphereObjectId is 0, so they need no clearing.
// depthMotion holds (depth, motion x, motion y, last frame's depth) in half precision: the filter's
// temporal pass reads it as its linear depth (.x) and, for the second type, reprojects with .yz and tests .w.
// Entries: second_type_guides.comp, second_type_guides.hlsl; one pipeline, two dispatches (clearPass).
#include "common/camera.h"
#include "common/caster_motion.h"
#include "common/caustic_hit.h"
#include "common/luminance.h"
#include "common/resources.h"
#include "common/specular_list.h"

CAUSTICS_SHARED_BEGIN

// Push constants (second_type_guides_bindings.h), 40 bytes.
struct SecondTypeGuideParams {
    uint2 size;            // the image, pixels
    uint sphereCapacity;   // the frame's sphere slots (caustics/sphere_capacity.h)
    uint clearPass;        // 1: zero every texel of sphereObjectId; 0: write each sphere's guides
    // 1: instanceMotion holds every instance's rows (common/caster_motion.h): a pixel whose glass moved
    // takes the glass's motion (docs/caustics.md "Moving objects").
    uint objectMotion;
    uint instanceCount;    // instances the rows cover
    // The guide images: W x H (listOrder 0), or one texel per list entry (listOrder 1, common/specular_list.h).
    uint2 guideSize;
    uint listOrder;
    uint pad;
};

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

// A receiver seen through a glass that moved (docs/caustics.md "Moving objects"): what the glass shows
// moves with it, the lens and the caustic under it alike, so the guide's motion is the glass point's
// (glassNow at this pixel, glassBefore where it was last frame, both world) and last frame's depth is
// the receiver point's carried by the glass's motion (receiverBefore).
CAUSTICS_FN SecondTypeGuide secondTypeGuideThroughMovedGlass(CameraConstants c, SecondTypeGuide g, float3 glassNow,
                                                             float3 glassBefore, float3 receiverBefore, float2 size) {
    float4 now = guideClip(c.viewProj, glassNow);
    float4 before = guideClip(c.prevViewProj, glassBefore);
    float4 receiver = guideClip(c.prevViewProj, receiverBefore);
    bool seen = before.w > 0.0f && now.w > 0.0f && receiver.w > 0.0f;
    SecondTypeGuide r = g;
    r.motion = seen ? guideTexel(before, size) - guideTexel(now, size) : splat2(kGuideNoHistory);
    r.previousDepth = seen ? receiver.w : 0.0f;
    return r;
}
CAUSTICS_SHARED_END

#if !defined(CAUSTICS_LANG_CPP)
#include "bindings/second_type_guides.h"   // generated from passes/backward_trace/second_type_guides_bindings.h

// Clear pass: one thread per guide texel (the guide grid). Sphere pass: one thread per sphere slot,
// kSpecularListRow to a row (the list's grid: at least as many threads as sphere slots).
void secondTypeGuidesThread(uint2 id) {
    if (params.clearPass != 0u) {
        if (id.x < params.guideSize.x && id.y < params.guideSize.y) CAUSTICS_IMAGE_STORE_UINT(sphereObjectId, int2(id), 0u);
        return;
    }
    uint slot = (id.y << kSpecularListRowShift) + id.x;
    if (slot >= min(countersLoad(kStatSpheres), params.sphereCapacity)) return;
    CausticSphere s = spheresLoad(slot);
    // A path that took a less probable lobe (a Fresnel reflection off the glass, say) gathers a legitimate
    // sample of the pixel's estimate from another receiver; its guides would keep the filter from
    // averaging that sample with its neighbours', so it leaves the pixel to the fill, which gives it the
    // guides of a neighbour's likely path (docs/caustics.md "Second-type guides").
    if (s.likelyPath == 0u) return;
    SecondTypeGuide g = secondTypeGuide(camera, s, float2(params.size));
    int2 p = int2(int(s.pixel % params.size.x), int(s.pixel / params.size.x));
    uint glass = CAUSTICS_TEXEL_UINT(gObjectId, p);   // the instance the camera sees at the pixel, + 1
    if (params.objectMotion != 0u && glass - 1u < params.instanceCount) {
        uint r = kCasterMotionRowsPerInstance * (glass - 1u);
        float4 r0 = instanceMotionLoad(r), r1 = instanceMotionLoad(r + 1u), r2 = instanceMotionLoad(r + 2u);
        float3 glassNow = cameraWorldPosition(camera, float2(p) + 0.5f, CAUSTICS_TEXEL(gLinearDepth, p).r);
        float3 glassBefore = instanceRowsApply(r0, r1, r2, glassNow);
        float3 moved = glassBefore - glassNow;
        if (dot(moved, moved) > 1e-10f)   // over 10 um: not rounding
            g = secondTypeGuideThroughMovedGlass(camera, g, glassNow, glassBefore, instanceRowsApply(r0, r1, r2, s.centre),
                                                 float2(params.size));
    }
    int2 t = SPECULAR_INPUT_TEXEL(p, params.listOrder);   // a sphere's pixel is listed
    if (t.x < 0) return;
    CAUSTICS_IMAGE_STORE(depthMotion, t, float4(g.linearDepth, g.motion.x, g.motion.y, g.previousDepth));
    CAUSTICS_IMAGE_STORE(normal, t, float4(g.normal, g.photonWeight));
    CAUSTICS_IMAGE_STORE_UINT(sphereObjectId, t, g.objectId);
}
#endif

#endif  // CAUSTICS_PASS_SECOND_TYPE_GUIDES_H
