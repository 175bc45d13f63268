// Light-space G-buffer (mirror of shaders/vulkan/caustic_maps/caustic_map.frag): world position
// (w = 1 where covered), outward shading normal, objectId (instance index + 1; 0 = empty).
struct CausticMapVaryings {
    float4 position : SV_Position;
    float3 worldPos : TEXCOORD0;
    float3 normal : TEXCOORD1;
    nointerpolation uint instance : TEXCOORD2;
};
struct CausticMapTargets {
    float4 position : SV_Target0;
    float4 normal : SV_Target1;
    uint objectId : SV_Target2;
};

CausticMapTargets main(CausticMapVaryings i) {
    CausticMapTargets o;
    o.position = float4(i.worldPos, 1.0f);
    o.normal = float4(normalize(i.normal), 0.0f);
    o.objectId = i.instance + 1u;
    return o;
}
