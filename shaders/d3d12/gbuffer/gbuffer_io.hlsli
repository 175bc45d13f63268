#ifndef CAUSTICS_D3D12_GBUFFER_IO_HLSLI
#define CAUSTICS_D3D12_GBUFFER_IO_HLSLI
// Mirror of shaders/vulkan/gbuffer/gbuffer_io.glsl: scene space 0, camera space 1, the instance index
// as a push constant (b0, space999); vertex pulling, no input layout.
#define SCENE_UNIFORM_TEXTURE_INDEX
#define SCENE_NO_TLAS
#include "scene/scene.hlsli"
#include "scene/camera.hlsli"

struct CameraBlock { CameraConstants camera; };
ConstantBuffer<CameraBlock> cameraBlock : register(b0, space1);
struct DrawConstants { uint instanceIndex; };
ConstantBuffer<DrawConstants> draw : register(b0, space999);

struct GBufferVaryings {
    float4 position : SV_Position;
    float3 worldPos : TEXCOORD0;
    float3 normal : TEXCOORD1;
    float2 uv : TEXCOORD2;
};
#endif
