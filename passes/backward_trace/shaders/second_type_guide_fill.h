#ifndef CAUSTICS_PASS_SECOND_TYPE_GUIDE_FILL_H
#define CAUSTICS_PASS_SECOND_TYPE_GUIDE_FILL_H
// Completes the second type's guides, in the shared dialect (docs/shaders.md; docs/caustics.md
// "Second-type guides"). Two dispatches of one pipeline (glassPass):
// - caustics.secondTypeGuides.fill: where this frame's backward sample made no sphere (it was reflected
//   away, with probability R, or left the scene) or made one along a less probable lobe (its guides are
//   not written: second_type_guides.h), the pixel's second type is a legitimate zero of the estimate, but
//   with guide id 0 the filter could not average it with its neighbours and it would stay a hole. It takes
//   the guides of the first of its 8 neighbours (fixed order: deterministic) that has a sphere and shows
//   the same object in the camera G-buffer (the same glass). Then every pixel with a guide counts the
//   neighbours whose sphere-written guide agrees with its own (guidesAgree); with fewer than
//   kGuideMinAgreeing its receiver is no surface the a-trous passes can follow (through many curved
//   interfaces each jittered ray reaches another point, depth or object), so it is marked
//   (kGuideGlassFlag in objectId) to be filtered on the glass instead.
//   In place: a thread writes only its own pixel's depthMotion and normal, and only where the sphere pass
//   wrote no guide; it reads them only at pixels the sphere pass wrote (sphereObjectId, which no thread
//   here writes, says which), so no thread reads a texel another one writes. The sphere-written textures
//   are not copied: at 1080p that copy was the second type's largest transient.
// - caustics.secondTypeGuides.glass: a marked pixel takes the guides of the glass the camera sees (its
//   G-buffer depth, normal and object id, the glass point's motion), as the merged filter uses for every
//   pixel; its photon weight stays. Only its own texels.
// Entries: second_type_guide_fill.comp, .hlsl.
#include "common/caster_motion.h"
#include "common/resources.h"
#include "common/specular_list.h"
#include "second_type_guide.h"

CAUSTICS_SHARED_BEGIN
// Push constants (second_type_guide_fill_bindings.h), 24 bytes.
struct SecondTypeGuideFillParams {
    uint2 size;       // the image, pixels
    uint listOrder;   // 1: the guides hold one texel per list entry (common/specular_list.h)
    uint glassPass;   // 0: caustics.secondTypeGuides.fill; 1: caustics.secondTypeGuides.glass
    // 1: instanceMotion holds every instance's rows (common/caster_motion.h): a marked pixel whose glass
    // moved takes the glass point's motion (docs/caustics.md "Moving objects").
    uint objectMotion;
    uint instanceCount;   // instances the rows cover
};

// objectId's mark between the two dispatches: the pixel is filtered on the glass (ids are instance + 1,
// far below it).
CAUSTICS_CONST uint kGuideGlassFlag = 0x80000000u;
// A pixel keeps its receiver's guides when at least this many of its 8 neighbours' sphere-written guides
// agree with them (docs/caustics.md "Second-type guides": a lone receiver sample is one the a-trous passes
// cannot spread; two agreeing neighbours make a patch of three).
CAUSTICS_CONST uint kGuideMinAgreeing = 2u;
// Guides agree where the a-trous passes' first step would weigh the pair (atrous.h atrousPairWeight, the
// second type's depth jitter): the same receiver, depths within 3 % (its 2.2 % at step 1 plus the pixel of
// slope the jitter adds) and normals within 8 degrees (the a-trous normal term, the cosine's 128th power,
// above 0.27).
CAUSTICS_CONST float kGuideAgreeDepth = 0.03f;
CAUSTICS_CONST float kGuideAgreeCosine = 0.99f;
CAUSTICS_FN bool guidesAgree(float depthA, float3 normalA, uint idA, float depthB, float3 normalB, uint idB) {
    return idA == idB && abs(depthA - depthB) <= kGuideAgreeDepth * max(depthA, depthB) && dot(normalA, normalB) >= kGuideAgreeCosine;
}

// The k-th neighbour (k < 8): the four edge neighbours first, then the diagonals.
CAUSTICS_FN int2 guideFillNeighbour(uint k) {
    int sign = (k & 1u) == 0u ? 1 : -1;
    if (k < 2u) return int2(sign, 0);
    if (k < 4u) return int2(0, sign);
    return int2(sign, k < 6u ? 1 : -1);
}
CAUSTICS_SHARED_END

#if !defined(CAUSTICS_LANG_CPP)
#include "bindings/second_type_guide_fill.h"   // generated from passes/backward_trace/second_type_guide_fill_bindings.h

// The pixel and guide texel of thread id: one thread per pixel, or, in list order, per listed entry (its
// texel; the pixel from the list): only listed pixels have guides there. x < 0: no pixel.
void secondTypeGuideFillTexels(uint2 id, out int2 p, out int2 t) {
    p = int2(id);
    t = int2(id);
    if (params.listOrder != 0u) {
        uint entry = (id.y << kSpecularListRowShift) + id.x;
        if (entry >= listCountLoad(0u)) {
            p = int2(-1, -1);
            return;
        }
        uint pixel = specularPixelsLoad(entry);
        p = int2(int(pixel % params.size.x), int(pixel / params.size.x));
    } else if (id.x >= params.size.x || id.y >= params.size.y) {
        p = int2(-1, -1);
    }
}

// The receiver id of p's k-th neighbour q (guideFillNeighbour) where the sphere pass wrote its guide, 0
// where it did not or q lies outside the view or the list; tq its guide texel.
uint secondTypeNeighbourSphere(int2 p, uint k, out int2 q, out int2 tq) {
    q = p + guideFillNeighbour(k);
    tq = int2(-1, -1);
    if (q.x < 0 || q.y < 0 || q.x >= int(params.size.x) || q.y >= int(params.size.y)) return 0u;
    tq = SPECULAR_INPUT_TEXEL(q, params.listOrder);
    return tq.x < 0 ? 0u : CAUSTICS_TEXEL_UINT(sphereObjectId, tq);
}

// How many of p's 8 neighbours have a sphere-written guide that agrees with (depth, n, id).
uint secondTypeGuideAgreeing(int2 p, float depth, float3 n, uint id) {
    uint agreeing = 0u;
    for (uint k = 0u; k < 8u; ++k) {
        int2 q, tq;
        uint source = secondTypeNeighbourSphere(p, k, q, tq);
        if (source != 0u &&
            guidesAgree(depth, n, id, CAUSTICS_IMAGE_LOAD(depthMotion, tq).x, CAUSTICS_IMAGE_LOAD(normal, tq).xyz, source))
            ++agreeing;
    }
    return agreeing;
}

// caustics.secondTypeGuides.glass: a marked pixel's guides become the glass's.
void secondTypeGuideGlass(int2 p, int2 t) {
    uint id = CAUSTICS_IMAGE_LOAD_UINT(objectId, t);
    if ((id & kGuideGlassFlag) == 0u) return;
    uint glass = CAUSTICS_TEXEL_UINT(cameraObjectId, p);
    float depth = CAUSTICS_TEXEL(cameraLinearDepth, p).r;
    float3 glassNow = cameraWorldPosition(camera, float2(p) + 0.5f, depth);
    float3 glassBefore = glassNow;
    if (params.objectMotion != 0u && glass - 1u < params.instanceCount) {
        uint r = kCasterMotionRowsPerInstance * (glass - 1u);
        glassBefore = instanceRowsApply(instanceMotionLoad(r), instanceMotionLoad(r + 1u), instanceMotionLoad(r + 2u), glassNow);
    }
    float3 motion = glassGuideMotion(camera, glassNow, glassBefore, float2(params.size));
    float weight = CAUSTICS_IMAGE_LOAD(normal, t).w;   // the pixel's own photon weight stays
    CAUSTICS_IMAGE_STORE(depthMotion, t, float4(max(depth, kGuideMinDepth), motion.x, motion.y, motion.z));
    CAUSTICS_IMAGE_STORE(normal, t, float4(CAUSTICS_TEXEL(cameraNormal, p).xyz, weight));
    CAUSTICS_IMAGE_STORE_UINT(objectId, t, glass);
}

void secondTypeGuideFillThread(uint2 id) {
    int2 p, t;
    secondTypeGuideFillTexels(id, p, t);
    if (p.x < 0) return;
    if (params.glassPass != 0u) {
        secondTypeGuideGlass(p, t);
        return;
    }
    uint surface = CAUSTICS_TEXEL_UINT(cameraObjectId, p);
    uint own = CAUSTICS_TEXEL_UINT(sphereObjectId, t);
    float4 depthMotionHere = float4(0.0f, 0.0f, 0.0f, 0.0f), normalHere = float4(0.0f, 0.0f, 0.0f, 0.0f);
    uint idHere = own;
    if (own != 0u) {   // the sphere pass wrote the pixel's depth, motion and normal
        depthMotionHere = CAUSTICS_IMAGE_LOAD(depthMotion, t);
        normalHere = CAUSTICS_IMAGE_LOAD(normal, t);
    } else {
        for (uint k = 0u; k < 8u && surface != 0u; ++k) {
            int2 q, tq;
            uint source = secondTypeNeighbourSphere(p, k, q, tq);
            if (source == 0u || CAUSTICS_TEXEL_UINT(cameraObjectId, q) != surface) continue;
            depthMotionHere = CAUSTICS_IMAGE_LOAD(depthMotion, tq);
            // A filled pixel's photon weight (.w) is stored negated: its sample is not the neighbour's, so the
            // filter's shot-noise estimate takes the weight but not the pixel's luminance (variance.h).
            normalHere = CAUSTICS_IMAGE_LOAD(normal, tq);
            normalHere.w = -abs(normalHere.w);
            idHere = source;
            break;
        }
        CAUSTICS_IMAGE_STORE(depthMotion, t, depthMotionHere);
        CAUSTICS_IMAGE_STORE(normal, t, normalHere);
    }
    // A receiver too few neighbours agree with, or none (no sphere here or beside it), is filtered on the
    // glass (the glass pass): with id 0 the pixel would keep no history from frame to frame. Only a
    // specular pixel (one the backward pass traces; in the screen layout the others have no second type)
    // takes the glass, so both layouts give the same guides.
    bool listed = params.listOrder != 0u || gbufferTexelIsSpecular(surface, CAUSTICS_TEXEL(cameraOptics, p));
    if (surface != 0u && listed &&
        (idHere == 0u || secondTypeGuideAgreeing(p, depthMotionHere.x, normalHere.xyz, idHere) < kGuideMinAgreeing))
        idHere |= kGuideGlassFlag;
    CAUSTICS_IMAGE_STORE_UINT(objectId, t, idHere);
}
#endif

#endif  // CAUSTICS_PASS_SECOND_TYPE_GUIDE_FILL_H
