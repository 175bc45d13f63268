// A host G-buffer's own object ids -> the module's (mirror of shaders/vulkan/gbuffer/remap_object_ids.comp):
// binary search of the host's (hostId, moduleId) pairs, sorted by hostId; unlisted ids become 0.
Texture2D<uint> hostObjectId : register(t0, space0);
ByteAddressBuffer pairs : register(t1, space0);
RWTexture2D<uint> moduleObjectId : register(u2, space0);

struct Params { uint2 size; uint pairCount; uint pad; };
ConstantBuffer<Params> params : register(b0, space999);

[numthreads(8, 8, 1)]
void main(uint3 id : SV_DispatchThreadID) {
    if (any(id.xy >= params.size)) return;
    uint hostId = hostObjectId.Load(int3(id.xy, 0));
    uint lo = 0u, hi = params.pairCount;   // first pair with pair.x >= hostId
    while (lo < hi) {
        uint mid = (lo + hi) / 2u;
        if (pairs.Load(8u * mid) < hostId) lo = mid + 1u; else hi = mid;
    }
    uint moduleId = 0u;
    if (lo < params.pairCount) {
        uint2 pair = pairs.Load2(8u * lo);
        if (pair.x == hostId) moduleId = pair.y;
    }
    moduleObjectId[id.xy] = moduleId;
}
