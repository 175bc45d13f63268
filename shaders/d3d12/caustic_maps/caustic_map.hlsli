#ifndef CAUSTICS_D3D12_CAUSTIC_MAP_HLSLI
#define CAUSTICS_D3D12_CAUSTIC_MAP_HLSLI
// std430 caustics::CausticMapGpu (176 bytes), read from a ByteAddressBuffer (mirror of
// shaders/vulkan/caustic_maps/caustic_map.glsl).
struct CausticMap {
    float3 origin;    uint light;
    float3 right;     float extent;
    float3 up;        uint orthographic;
    float3 forward;   float nearPlane;
    float3 intensity; float cosInner;
    float3 spotAxis;  float cosOuter;
    Mat4 viewProj;
    float range;      // KHR_lights_punctual range, 0 = infinite
    float photons;    // this layer's photons per frame; 0: raysPerTexel per texel
    uint cluster;     // the layer's number among its light's layers
    uint ownerRow;    // row of the instance -> layer ownership table
};

CausticMap loadCausticMap(ByteAddressBuffer b, uint index) {
    uint o = 176u * index;
    CausticMap m;
    float4 a = asfloat(b.Load4(o)), r = asfloat(b.Load4(o + 16u)), u = asfloat(b.Load4(o + 32u));
    float4 f = asfloat(b.Load4(o + 48u)), i = asfloat(b.Load4(o + 64u)), s = asfloat(b.Load4(o + 80u));
    m.origin = a.xyz; m.light = asuint(a.w);
    m.right = r.xyz; m.extent = r.w;
    m.up = u.xyz; m.orthographic = asuint(u.w);
    m.forward = f.xyz; m.nearPlane = f.w;
    m.intensity = i.xyz; m.cosInner = i.w;
    m.spotAxis = s.xyz; m.cosOuter = s.w;
    m.viewProj = loadMat4(b, o + 96u);
    float4 p = asfloat(b.Load4(o + 160u));
    m.range = p.x; m.photons = p.y; m.cluster = asuint(p.z); m.ownerRow = asuint(p.w);
    return m;
}

// Does layer m own scene instance `instance` (mirror of CAUSTIC_LAYER_OWNS in caustic_map.glsl)?
bool causticLayerOwns(ByteAddressBuffer owners, CausticMap m, uint instanceCount, uint instance) {
    return owners.Load(4u * (m.ownerRow * instanceCount + instance)) == m.cluster + 1u;
}
#endif
