#ifndef CAUSTICS_PASS_SECOND_TYPE_GUIDES_H
#define CAUSTICS_PASS_SECOND_TYPE_GUIDES_H
// The second type's own filter guides, in the shared dialect (docs/shaders.md; docs/caustics.md
// "Second-type guides"): a pixel whose camera path went through glass shows a caustic that lies on the
// receiver the path reached, not on the glass the G-buffer holds. So the receiver's linear depth (clip w),
// its normal (facing the arriving path), its object id and its screen motion (where the receiver point
// was last frame minus where it is now, pixels) are written at the pixel from that pixel's sphere
// (caustics.backward: at most one per pixel). Pixels without a sphere hold zeros (id 0: no receiver).
// depthMotion holds (depth, motion x, motion y, last frame's depth): the filter's temporal pass reads it
// as its linear depth (.x) and, for the second type, reprojects with .yz and tests .w.
// Entries: second_type_guides.comp, second_type_guides.hlsl; one pipeline, two dispatches (clearPass).
#include "common/resources.h"

CAUSTICS_SHARED_BEGIN

// caustics::CameraConstants (passes/internal/caustics/camera_constants.h) with each matrix as its four
// columns (the dialect has no matrices); `frame` holds uints and is not read here.
struct GuideCamera {
    float4 view[4];
    float4 proj[4];
    float4 viewProj[4];
    float4 invViewProj[4];
    float4 prevViewProj[4];
    float4 eye;
    float4 forward;
    float4 right;
    float4 up;
    float4 clip;
    float4 frame;
};

// caustics::CausticSphere (passes/internal/caustics/caustic_passes.h), 64 bytes.
struct GuideSphere {
    float3 centre;
    float radius;
    float3 transmittance;
    uint objectId;
    float3 normal;
    uint pixel;
    float3 outgoing;
    float pad;
};

// Push constants (second_type_guides_bindings.h), 16 bytes.
struct SecondTypeGuideParams {
    uint2 size;            // the image, pixels
    uint sphereCapacity;   // the frame's sphere slots (caustics/sphere_capacity.h)
    uint clearPass;        // 1: zero every pixel's guides; 0: write each sphere's
};

CAUSTICS_CONST uint kGuideSphereCountSlot = 3u;   // caustics.stats' kStatSpheres (caustic_passes.h)
// Motion of a receiver point that was behind last frame's camera: far off screen, so no history is found.
CAUSTICS_CONST float kGuideNoHistory = -1.0e9f;
// A receiver reached by a reflection can lie behind the camera (clip w <= 0): the filter divides by
// depths, so the guide holds |w|, at least this (metres).
CAUSTICS_CONST float kGuideMinDepth = 1.0e-3f;

struct SecondTypeGuide {
    float linearDepth;   // |clip w| of the receiver point, at least kGuideMinDepth
    float2 motion;       // last frame's texel-centre position minus this frame's, pixels
    float previousDepth; // clip w last frame (0: behind last frame's camera, no history)
    float3 normal;
    uint objectId;
};

CAUSTICS_FN float4 guideClip(float4 c0, float4 c1, float4 c2, float4 c3, float3 x) {
    return c0 * x.x + c1 * x.y + c2 * x.z + c3;
}

// Texel-centre coordinates of a clip-space point (pixel (i, j)'s centre is (i, j)), as the filter's
// reprojection computes them (docs/caustics.md "Filter").
CAUSTICS_FN float2 guideTexel(float4 clip, float2 size) {
    return (float2(clip.x, clip.y) / clip.w * 0.5f + 0.5f) * size - 0.5f;
}

CAUSTICS_FN SecondTypeGuide secondTypeGuide(GuideCamera c, GuideSphere s, float2 size) {
    float4 now = guideClip(c.viewProj[0], c.viewProj[1], c.viewProj[2], c.viewProj[3], s.centre);
    float4 before = guideClip(c.prevViewProj[0], c.prevViewProj[1], c.prevViewProj[2], c.prevViewProj[3], s.centre);
    SecondTypeGuide g;
    g.linearDepth = max(abs(now.w), kGuideMinDepth);
    bool seen = before.w > 0.0f && now.w > 0.0f;
    g.motion = seen ? guideTexel(before, size) - guideTexel(now, size) : splat2(kGuideNoHistory);
    g.previousDepth = seen ? before.w : 0.0f;
    g.normal = s.normal;
    g.objectId = s.objectId;
    return g;
}

CAUSTICS_SHARED_END

#if !defined(CAUSTICS_LANG_CPP)
#include "bindings/second_type_guides.h"   // generated from passes/backward_trace/second_type_guides_bindings.h

// Clear pass: one thread per pixel. Sphere pass: one thread per sphere slot (row-major over the image
// grid, which has at least as many threads as sphere slots).
void secondTypeGuidesThread(uint2 id) {
    if (id.x >= params.size.x || id.y >= params.size.y) return;
    if (params.clearPass != 0u) {
        CAUSTICS_IMAGE_STORE(depthMotion, int2(id), float4(0.0f, 0.0f, 0.0f, 0.0f));
        CAUSTICS_IMAGE_STORE(normal, int2(id), float4(0.0f, 0.0f, 0.0f, 0.0f));
        CAUSTICS_IMAGE_STORE_UINT(objectId, int2(id), 0u);
        return;
    }
    uint slot = id.y * params.size.x + id.x;
    if (slot >= min(countersLoad(kGuideSphereCountSlot), params.sphereCapacity)) return;
    GuideSphere s = spheresLoad(slot);
    SecondTypeGuide g = secondTypeGuide(camera, s, float2(params.size));
    int2 p = int2(int(s.pixel % params.size.x), int(s.pixel / params.size.x));
    CAUSTICS_IMAGE_STORE(depthMotion, p, float4(g.linearDepth, g.motion.x, g.motion.y, g.previousDepth));
    CAUSTICS_IMAGE_STORE(normal, p, float4(g.normal, 0.0f));
    CAUSTICS_IMAGE_STORE_UINT(objectId, p, g.objectId);
}
#endif

#endif  // CAUSTICS_PASS_SECOND_TYPE_GUIDES_H
