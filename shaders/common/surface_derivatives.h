#ifndef CAUSTICS_COMMON_SURFACE_DERIVATIVES_H
#define CAUSTICS_COMMON_SURFACE_DERIVATIVES_H
// World-space data of a hit triangle that common/ray_differential.h needs for the derivative of the
// interpolated shading normal (Igehy 1999 sec. 3.2): the two edges, the vertex-normal differences and
// the unnormalised interpolated normal. Reads the scene through the accessors of common/scene.h (the
// per-API scene shim, or a C++ caller, defines them; docs/shaders.md "Scene API").
#include "common/ray_differential.h"
#include "common/scene.h"

CAUSTICS_SHARED_BEGIN
struct SurfaceDerivatives {
    float3 e1;    // p1 - p0 (world)
    float3 e2;    // p2 - p0 (world)
    float3 dn1;   // n1 - n0 (normal matrix applied, not normalised)
    float3 dn2;   // n2 - n0
    float3 nU;    // interpolated normal (normal matrix applied, not normalised)
};

CAUSTICS_FN SurfaceDerivatives sceneSurfaceDerivatives(uint instance, uint primitive, float2 barycentrics) {
    GpuInstance inst = sceneInstance(instance);
    uint3 tri = sceneTriangle(inst, primitive);
    uint i0 = tri.x, i1 = tri.y, i2 = tri.z;
    float3 p0 = scenePosition(i0);
    float3 n0 = sceneVertex(i0).normal;
    float3 n1 = sceneVertex(i1).normal;
    float3 n2 = sceneVertex(i2).normal;
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
CAUSTICS_FN void shadingNormalDerivatives(SurfaceDerivatives s, RayDifferential rd, CAUSTICS_OUT(float3) dNdx,
                                          CAUSTICS_OUT(float3) dNdy) {
    dNdx = splat3(0.0f);
    dNdy = splat3(0.0f);
    if (dot(s.nU, s.nU) <= 1e-12f) return;
    dNdx = shadingNormalDerivative(s.e1, s.e2, s.dn1, s.dn2, s.nU, rd.dPdx);
    dNdy = shadingNormalDerivative(s.e1, s.e2, s.dn1, s.dn2, s.nU, rd.dPdy);
}
CAUSTICS_SHARED_END
#endif  // CAUSTICS_COMMON_SURFACE_DERIVATIVES_H
