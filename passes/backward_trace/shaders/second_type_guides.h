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
#include "common/caster_motion.h"
#include "common/resources.h"
#include "common/specular_list.h"
#include "second_type_guide.h"

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
