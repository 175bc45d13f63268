#ifndef CAUSTICS_BACKWARD_SURFACE_DERIVATIVES_GLSL
#define CAUSTICS_BACKWARD_SURFACE_DERIVATIVES_GLSL
// World-space data of a hit triangle that common/ray_differential.h needs for the derivative of the
// interpolated shading normal (Igehy 1999 sec. 3.2): the two edges, the vertex-normal differences and
// the unnormalised interpolated normal. Include after scene/scene.glsl.
#include "common/ray_differential.h"

struct SurfaceDerivatives {
    vec3 e1, e2;     // p1 - p0, p2 - p0 (world)
    vec3 dn1, dn2;   // n1 - n0, n2 - n0 (normal matrix applied, not normalised)
    vec3 nU;         // interpolated normal (normal matrix applied, not normalised)
};

SurfaceDerivatives sceneSurfaceDerivatives(uint instance, uint primitive, vec2 barycentrics) {
    GpuInstance inst = sceneInstances[instance];
    uint base = inst.firstIndex + 3u * primitive;
    uint i0 = inst.firstVertex + sceneIndices[base];
    uint i1 = inst.firstVertex + sceneIndices[base + 1u];
    uint i2 = inst.firstVertex + sceneIndices[base + 2u];
    mat3 o2w = mat3(inst.objectToWorld);
    mat3 n2w = mat3(inst.normalToWorld);
    vec3 p0 = scenePosition(i0);
    vec3 n0 = sceneVertices[i0].normal, n1 = sceneVertices[i1].normal, n2 = sceneVertices[i2].normal;
    SurfaceDerivatives s;
    s.e1 = o2w * (scenePosition(i1) - p0);
    s.e2 = o2w * (scenePosition(i2) - p0);
    s.dn1 = n2w * (n1 - n0);
    s.dn2 = n2w * (n2 - n0);
    s.nU = n2w * (n0 + barycentrics.x * (n1 - n0) + barycentrics.y * (n2 - n0));
    return s;
}

// Derivatives of the (unflipped) shading normal along the transferred differential's dPdx, dPdy.
// A triangle without usable vertex normals is flat: zero derivatives.
void shadingNormalDerivatives(SurfaceDerivatives s, RayDifferential rd, out vec3 dNdx, out vec3 dNdy) {
    dNdx = vec3(0.0);
    dNdy = vec3(0.0);
    if (dot(s.nU, s.nU) <= 1e-12) return;
    dNdx = shadingNormalDerivative(s.e1, s.e2, s.dn1, s.dn2, s.nU, rd.dPdx);
    dNdy = shadingNormalDerivative(s.e1, s.e2, s.dn1, s.dn2, s.nU, rd.dPdy);
}
#endif
