#ifndef CAUSTICS_BACKWARD_SURFACE_DERIVATIVES_HLSLI
#define CAUSTICS_BACKWARD_SURFACE_DERIVATIVES_HLSLI
// Mirror of shaders/vulkan/backward_trace/surface_derivatives.glsl: the world-space data of a hit
// triangle that common/ray_differential.h needs for the shading normal's derivatives (Igehy 1999
// sec. 3.2). Include after scene/scene.hlsli.
#include "common/ray_differential.h"

struct SurfaceDerivatives {
    float3 e1, e2;     // p1 - p0, p2 - p0 (world)
    float3 dn1, dn2;   // n1 - n0, n2 - n0 (normal matrix applied, not normalised)
    float3 nU;         // interpolated normal (normal matrix applied, not normalised)
};

SurfaceDerivatives sceneSurfaceDerivatives(uint instance, uint primitive, float2 barycentrics) {
    GpuInstance inst = sceneInstance(instance);
    uint base = inst.firstIndex + 3u * primitive;
    uint i0 = inst.firstVertex + sceneIndex(base);
    uint i1 = inst.firstVertex + sceneIndex(base + 1u);
    uint i2 = inst.firstVertex + sceneIndex(base + 2u);
    float3 p0 = scenePosition(i0);
    float3 n0 = sceneVertex(i0).normal, n1 = sceneVertex(i1).normal, n2 = sceneVertex(i2).normal;
    SurfaceDerivatives s;
    s.e1 = mat3Mul(inst.objectToWorld, scenePosition(i1) - p0);
    s.e2 = mat3Mul(inst.objectToWorld, scenePosition(i2) - p0);
    s.dn1 = mat3Mul(inst.normalToWorld, n1 - n0);
    s.dn2 = mat3Mul(inst.normalToWorld, n2 - n0);
    s.nU = mat3Mul(inst.normalToWorld, n0 + barycentrics.x * (n1 - n0) + barycentrics.y * (n2 - n0));
    return s;
}

// Derivatives of the (unflipped) shading normal along the transferred differential's dPdx, dPdy.
// A triangle without usable vertex normals is flat: zero derivatives.
void shadingNormalDerivatives(SurfaceDerivatives s, RayDifferential rd, out float3 dNdx, out float3 dNdy) {
    dNdx = (float3)0.0f;
    dNdy = (float3)0.0f;
    if (dot(s.nU, s.nU) <= 1e-12f) return;
    dNdx = shadingNormalDerivative(s.e1, s.e2, s.dn1, s.dn2, s.nU, rd.dPdx);
    dNdy = shadingNormalDerivative(s.e1, s.e2, s.dn1, s.dn2, s.nU, rd.dPdy);
}
#endif
