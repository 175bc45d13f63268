// Caustic visibility map (mirror of shaders/vulkan/caustic_maps/caustic_map.frag): the objectId
// (instance index + 1; 0 = empty) of the surface nearest the light, the only target the forward
// trace reads.
struct CausticMapVaryings {
    float4 position : SV_Position;
    nointerpolation uint instance : TEXCOORD0;
};

uint main(CausticMapVaryings i) : SV_Target0 { return i.instance + 1u; }
