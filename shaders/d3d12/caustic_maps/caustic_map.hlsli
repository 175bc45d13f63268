#ifndef CAUSTICS_D3D12_CAUSTIC_MAP_HLSLI
#define CAUSTICS_D3D12_CAUSTIC_MAP_HLSLI
// std430 caustics::CausticMapGpu (160 bytes), read from a ByteAddressBuffer (mirror of
// shaders/vulkan/caustic_maps/caustic_map.glsl).
struct CausticMap {
    float3 origin;    uint light;
    float3 right;     float extent;
    float3 up;        uint orthographic;
    float3 forward;   float nearPlane;
    float3 intensity; float cosInner;
    float3 spotAxis;  float cosOuter;
    Mat4 viewProj;
};

CausticMap loadCausticMap(ByteAddressBuffer b, uint index) {
    uint o = 160u * index;
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
    return m;
}
#endif
