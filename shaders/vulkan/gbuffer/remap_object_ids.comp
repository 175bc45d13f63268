#version 460
#extension GL_EXT_samplerless_texture_functions : require
// A host G-buffer's own object ids -> the module's (docs/embedding.md, "Instance ids"): every pixel's
// host id is looked up in the host's map, (hostId, moduleId) pairs sorted by hostId, by binary search;
// an id the map does not list becomes 0 (background: no caustic lands there, no backward ray starts).
layout(local_size_x = 8, local_size_y = 8) in;

layout(set = 0, binding = 0) uniform utexture2D hostObjectId;
layout(set = 0, binding = 1, std430) readonly buffer ObjectIdMap { uvec2 pairs[]; };
layout(set = 0, binding = 2, r32ui) uniform writeonly uimage2D moduleObjectId;

layout(push_constant) uniform Params {
    uvec2 size;
    uint pairCount;
    uint pad;
} params;

void main() {
    const ivec2 p = ivec2(gl_GlobalInvocationID.xy);
    if (any(greaterThanEqual(uvec2(p), params.size))) return;
    const uint hostId = texelFetch(hostObjectId, p, 0).r;
    uint lo = 0u, hi = params.pairCount;   // first pair with pairs[i].x >= hostId
    while (lo < hi) {
        const uint mid = (lo + hi) / 2u;
        if (pairs[mid].x < hostId) lo = mid + 1u; else hi = mid;
    }
    const uint moduleId = (lo < params.pairCount && pairs[lo].x == hostId) ? pairs[lo].y : 0u;
    imageStore(moduleObjectId, p, uvec4(moduleId));
}
