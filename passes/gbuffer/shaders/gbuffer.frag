#version 460
#extension GL_GOOGLE_include_directive : require
// Vulkan fragment entry of gbuffer; the body is gbuffer.h (docs/shaders.md).
#define CAUSTICS_STAGE_FRAG 1
#define SCENE_UNIFORM_TEXTURE_INDEX
#define SCENE_NO_TLAS
#include "common/scene_resources.h"
#include "gbuffer.h"
layout(location = 0) in vec3 inWorldPos;
layout(location = 1) in vec3 inNormal;
layout(location = 2) in vec2 inUv;
layout(location = 0) out vec4 outNormalRoughness;
layout(location = 1) out vec4 outAlbedoMetallic;
layout(location = 2) out vec4 outOptics;
layout(location = 3) out float outLinearDepth;
layout(location = 4) out uint outObjectId;
void main() {
    GBufferVaryings i;
    i.worldPos = inWorldPos;
    i.normal = inNormal;
    i.uv = inUv;
    GBufferTargets o = gbufferFragment(i);
    outNormalRoughness = o.normalRoughness;
    outAlbedoMetallic = o.albedoMetallic;
    outOptics = o.optics;
    outLinearDepth = o.linearDepth;
    outObjectId = o.objectId;
}
