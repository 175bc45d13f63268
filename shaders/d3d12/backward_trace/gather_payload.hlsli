#ifndef CAUSTICS_D3D12_GATHER_PAYLOAD_HLSLI
#define CAUSTICS_D3D12_GATHER_PAYLOAD_HLSLI
// Payload and attributes of the gather state object (DXR payloads and attributes must be structs).
struct GatherPayload { uint hitIndex; };
struct SphereAttributes { float2 unused; };   // 8 bytes, within maxAttributeBytes
#endif
