// The filter's tile state (mirror of shaders/vulkan/caustic_filter/tiles.comp; docs/caustics.md "Filter",
// "Tiles"): keepFrames | bit 31 after a frame with a photon in the tile, else one less than the largest
// state among the history texels its pixels reproject to.
#include "scene/camera.hlsli"
#include "caustic_filter/filter_common.hlsli"
struct CameraBlock { CameraConstants camera; };
ConstantBuffer<CameraBlock> cameraBlock : register(b0, space0);
Texture2D<float4> current : register(t1, space0);
Texture2D<float4> gLinearDepth : register(t2, space0);
Texture2D<uint> gObjectId : register(t3, space0);
Texture2D<uint> previousTiles : register(t4, space0);
RWTexture2D<uint> tileState : register(u5, space0);
struct Push { uint historyValid; uint keepFrames; };
ConstantBuffer<Push> pc : register(b0, space999);

groupshared uint sPhotons;
groupshared uint sCarried;

uint carriedState(float2 prev, int2 size) {
    int2 lo = max(int2(floor(prev)) - 1, int2(0, 0));
    int2 hi = min(int2(floor(prev)) + 2, size - 1);
    if (any(lo > hi)) return 0u;
    uint m = 0u;
    for (int ty = lo.y / kFilterTileSize; ty <= hi.y / kFilterTileSize; ++ty)
        for (int tx = lo.x / kFilterTileSize; tx <= hi.x / kFilterTileSize; ++tx)
            m = max(m, previousTiles.Load(int3(tx, ty, 0)) & kFilterTileKeepMask);
    return m;
}

[numthreads(8, 8, 1)]
void main(uint3 tid : SV_DispatchThreadID, uint3 group : SV_GroupID, uint index : SV_GroupIndex) {
    CameraConstants camera = cameraBlock.camera;
    if (index == 0u) {
        sPhotons = 0u;
        sCarried = 0u;
    }
    GroupMemoryBarrierWithGroupSync();
    int2 p = int2(tid.xy);
    int2 size = int2(camera.frame.xy);
    if (p.x < size.x && p.y < size.y) {
        float3 c = current.Load(int3(p, 0)).rgb;
        if (max(c.r, max(c.g, c.b)) > 0.0f) InterlockedOr(sPhotons, 1u);
        float depth = gLinearDepth.Load(int3(p, 0)).r;
        if (pc.historyValid != 0u && gObjectId.Load(int3(p, 0)) != 0u && depth > 0.0f) {
            float4 clip = mul(camera.prevViewProj, float4(cameraWorldPosition(camera, float2(p) + 0.5f, depth), 1.0f));
            if (clip.w > 0.0f) InterlockedMax(sCarried, carriedState((clip.xy / clip.w * 0.5f + 0.5f) * float2(size) - 0.5f, size));
        }
    }
    GroupMemoryBarrierWithGroupSync();
    if (index == 0u) tileState[int2(group.xy)] = sPhotons != 0u ? (pc.keepFrames | kFilterTilePhotons) : max(sCarried, 1u) - 1u;
}
