#version 460
#extension GL_GOOGLE_include_directive : require
// G-buffer fragment stage: writes the six targets of passes/include/caustics/gbuffer.h.
#include "gbuffer_io.glsl"

layout(location = 0) in vec3 inWorldPos;
layout(location = 1) in vec3 inNormal;
layout(location = 2) in vec2 inUv;

layout(location = 0) out vec4 outNormalRoughness;
layout(location = 1) out vec4 outAlbedoMetallic;
layout(location = 2) out vec4 outOptics;
layout(location = 3) out float outLinearDepth;
layout(location = 4) out uint outObjectId;

void main() {
    GpuInstance inst = sceneInstances[draw.instanceIndex];
    GpuMaterial m = sceneMaterials[inst.material];

    // Shading normal turned towards the viewer: the G-buffer holds the side that is seen, whatever the
    // winding (double-sided and thin-walled surfaces are seen from both sides). A degenerate
    // interpolated normal falls back to the facet normal from screen-space derivatives.
    vec3 toEye = camera.eye.xyz - inWorldPos;
    vec3 n = inNormal;
    if (dot(n, n) < 1e-12) n = cross(dFdx(inWorldPos), dFdy(inWorldPos));
    n = normalize(n);
    if (dot(n, toEye) < 0.0) n = -n;

    outNormalRoughness = vec4(n, m.roughness);
    outAlbedoMetallic = vec4(sceneBaseColor(m, inUv), m.metallic);
    outOptics = sceneOpticsEncoding(m);
    outLinearDepth = dot(inWorldPos - camera.eye.xyz, camera.forward.xyz);
    outObjectId = draw.instanceIndex + 1u;
}
