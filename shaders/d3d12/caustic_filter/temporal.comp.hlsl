// Temporal accumulation (SVGF, Schied et al. 2017, section 4.1; mirror of shaders/vulkan/
// caustic_filter/temporal.comp): bilinear history taps that pass the disocclusion test (object id,
// depth, normal), blended with weight 1/n, n = history length capped at maxHistory. prevViewProj is
// Vulkan's clip (y down) and is used as such: no rasterizer here. Dispatched over the tile list; a
// history texel exists only where last frame's slot map gave its tile a pool tile. Reads last frame's
// ping-ponged pool, writes this frame's (pre-exposed half precision) and the depth gradient.
#include "scene/camera.hlsli"
#include "caustic_filter/filter_common.hlsli"
struct CameraBlock { CameraConstants camera; };
ConstantBuffer<CameraBlock> cameraBlock : register(b0, space0);
Texture2D<float4> current : register(t1, space0);
Texture2D<float4> gLinearDepth : register(t2, space0);
Texture2D<float4> gNormal : register(t3, space0);
Texture2D<uint> gObjectId : register(t4, space0);
Texture2D<float4> historyColor : register(t5, space0);    // pool: rgb mean x pre-exposure, a deviation
Texture2D<uint2> historyGuides : register(t6, space0);    // pool
Texture2D<uint> previousSlots : register(t7, space0);
ByteAddressBuffer tiles : register(t8, space0);
RWTexture2D<float4> outColor : register(u9, space0);
RWTexture2D<uint2> outGuides : register(u10, space0);
RWTexture2D<uint> outGradient : register(u11, space0);
// motionGuides: gLinearDepth is the second type's guide (mirror of temporal.comp).
struct Push { uint historyValid; float maxHistory; float preExposure; float historyScale; uint motionGuides; };
ConstantBuffer<Push> pc : register(b0, space999);

static const float kHistoryRejectDeviations = 3.0f;
static const float kTrustedHistory = 4.0f;   // SVGF's threshold for trusting the temporal moments

// Last frame's pool texel of screen texel q, or (-1, -1) where its tile kept no history.
int2 historyTexel(int2 q) {
    uint slot = previousSlots.Load(int3(q / kFilterTileSize, 0));
    return slot == kFilterNoSlot ? int2(-1, -1) : filterPoolTexel(slot, filterLocal(q));
}

// E[l], per-frame variance of l, n of a history texel (this frame's pre-exposed units).
float3 historyMomentsAt(int2 h, FilterGuide g) {
    float4 c = historyColor.Load(int3(h, 0)) * pc.historyScale;
    return float3(filterLuminance(c.rgb), c.a * c.a, g.historyLength);
}

// True when this frame's caustic around p is inconsistent with the history (temporal.comp explains it).
bool historyRejected(int2 p, int2 nearest, int2 size, uint id) {
    float c = 0.0f, h = 0.0f, v = 0.0f, quantum = 0.0f;
    for (int dy = -1; dy <= 1; ++dy) {
        for (int dx = -1; dx <= 1; ++dx) {
            int2 q = p + int2(dx, dy), hq = nearest + int2(dx, dy);
            if (any(min(q, hq) < int2(0, 0)) || any(max(q, hq) >= size)) continue;
            if (gObjectId.Load(int3(q, 0)) != id) continue;
            int2 ht = historyTexel(hq);
            if (ht.x < 0) continue;
            FilterGuide g = filterUnpackGuide(historyGuides.Load(int3(ht, 0)));
            if (g.id != filterGuideId(id)) continue;
            float l = filterLuminance(current.Load(int3(q, 0)).rgb * pc.preExposure);
            float3 m = historyMomentsAt(ht, g);
            c += l;
            h += m.x;
            v += m.y;
            if (l > 0.0f) quantum = quantum > 0.0f ? min(quantum, l) : l;
        }
    }
    return abs(c - h) > kHistoryRejectDeviations * sqrt(v) + 2.0f * quantum;
}

bool sameSurface(int2 q, int2 size, uint id) {
    return all(q >= int2(0, 0)) && all(q < size) && gObjectId.Load(int3(q, 0)) == id;
}

// Smaller one-sided difference of linear depth along `axis` (no leniency across a depth edge).
float depthSlope(int2 p, int2 axis, int2 size, float z, uint id) {
    float slope = 3.0e38f;
    if (sameSurface(p + axis, size, id)) slope = gLinearDepth.Load(int3(p + axis, 0)).r - z;
    if (sameSurface(p - axis, size, id)) {
        float back = z - gLinearDepth.Load(int3(p - axis, 0)).r;
        if (abs(back) < abs(slope)) slope = back;
    }
    return slope < 3.0e38f ? slope : 0.0f;
}

[numthreads(8, 8, 1)]
void main(uint3 group : SV_GroupID, uint3 groupThread : SV_GroupThreadID) {
    CameraConstants camera = cameraBlock.camera;
    int2 p = filterTilePixel(tiles.Load(4u * group.x), groupThread.xy);
    int2 size = int2(camera.frame.xy);
    if (p.x >= size.x || p.y >= size.y) return;
    int2 pool = filterPoolTexel(group.x, int2(groupThread.xy));
    float3 cur = current.Load(int3(p, 0)).rgb * pc.preExposure;
    float l = filterLuminance(cur);
    float depth = gLinearDepth.Load(int3(p, 0)).r;
    float3 n = gNormal.Load(int3(p, 0)).xyz;
    uint objectId = gObjectId.Load(int3(p, 0));
    float3 color = cur;
    float moment2 = l * l;
    float historyLength = 1.0f;
    if (pc.historyValid != 0u && objectId != 0u && depth > 0.0f) {
        float3 world = cameraWorldPosition(camera, float2(p) + 0.5f, depth);
        float4 clip = mul(camera.prevViewProj, float4(world, 1.0f));
        float4 guide = gLinearDepth.Load(int3(p, 0));
        if (pc.motionGuides != 0u) clip.w = guide.w;
        if (clip.w > 0.0f) {
            // Texel-centre coordinates.
            float2 prev = pc.motionGuides != 0u ? float2(p) + guide.yz : (clip.xy / clip.w * 0.5f + 0.5f) * float2(size) - 0.5f;
            int2 base = int2(floor(prev));
            float2 f = prev - float2(base);
            float tolerance = clip.w * filterRelativeDepthTolerance(camera.forward.w, float(size.y), n,
                                                                   normalize(camera.eye.xyz - world));
            float3 hColor = (float3)0.0f;
            float3 hMoments = (float3)0.0f;
            float wSum = 0.0f;
            for (int i = 0; i < 4; ++i) {
                int2 o = int2(i & 1, i >> 1);
                int2 q = base + o;
                if (any(q < int2(0, 0)) || any(q >= size)) continue;
                int2 ht = historyTexel(q);
                if (ht.x < 0) continue;
                FilterGuide hg = filterUnpackGuide(historyGuides.Load(int3(ht, 0)));
                if (hg.id != filterGuideId(objectId)) continue;
                if (abs(hg.depth - clip.w) > tolerance) continue;
                if (dot(hg.normal, n) < 0.9f) continue;
                float w = (o.x == 1 ? f.x : 1.0f - f.x) * (o.y == 1 ? f.y : 1.0f - f.y);
                hColor += w * historyColor.Load(int3(ht, 0)).rgb * pc.historyScale;
                // Per-tap variance, not the moments (temporal.comp says why).
                hMoments += w * historyMomentsAt(ht, hg);
                wSum += w;
            }
            bool rejected = wSum > 0.01f && hMoments.z / wSum >= kTrustedHistory &&
                            historyRejected(p, int2(floor(prev + 0.5f)), size, objectId);
            if (wSum > 0.01f && !rejected) {
                hColor /= wSum;
                hMoments /= wSum;
                hMoments.y += hMoments.x * hMoments.x;   // back to E[l^2] of the blended history
                historyLength = min(hMoments.z + 1.0f, pc.maxHistory);
                float alpha = 1.0f / historyLength;
                color = lerp(hColor, cur, alpha);
                moment2 = lerp(hMoments.y, moment2, alpha);
            }
        }
    }
    float2 gradZ = float2(depthSlope(p, int2(1, 0), size, depth, objectId), depthSlope(p, int2(0, 1), size, depth, objectId));
    // The variance leaves as a standard deviation (temporal.comp says why).
    float lm = filterLuminance(color);
    outColor[pool] = filterNearestHalf(float4(color, sqrt(max(0.0f, moment2 - lm * lm))));
    outGuides[pool] = filterPackGuide(depth, historyLength, n, objectId);
    outGradient[pool] = filterPackHalf2(gradZ);
}
