#ifndef CAUSTICS_COMMON_RAY_DIFFERENTIAL_H
#define CAUSTICS_COMMON_RAY_DIFFERENTIAL_H
// Ray differentials (Igehy 1999, "Tracing ray differentials", SIGGRAPH): the derivatives of a ray's
// origin P and unit direction D with respect to the image coordinates x and y (one pixel each),
// carried through transfer, reflection and refraction with the surface's normal derivatives. The
// backward (second-type) pass uses them to size a pixel's gather disk on the diffuse receiver it
// sees through a specular chain (docs/caustics.md "Second-type footprint", docs/physics.md).
#include "common/camera.h"
#include "common/lang.h"
#include "common/specular_event.h"

CAUSTICS_SHARED_BEGIN

struct RayDifferential {
    float3 dPdx;
    float3 dPdy;
    float3 dDdx;
    float3 dDdy;
};

// Derivative of normalize(v) along dv (Igehy eq. 10): (v.v dv - (v.dv) v) / (v.v)^(3/2).
CAUSTICS_FN float3 normalizeDerivative(float3 v, float3 dv) {
    float vv = dot(v, v);
    return (vv * dv - dot(v, dv) * v) / (vv * sqrt(vv));
}

// Primary ray of a pinhole camera through continuous pixel `pixel` (cameraRayDirection): P is the
// eye for every pixel (dP = 0); the unnormalised direction moves by 2 tan(fov/2) aspect / width
// along `right` per pixel in x and by 2 tan(fov/2) / height against `up` per pixel in y.
CAUSTICS_FN RayDifferential pinholeRayDifferential(PinholeCamera c, float2 pixel) {
    float sx = 2.0f * pixel.x / c.width - 1.0f;
    float sy = 1.0f - 2.0f * pixel.y / c.height;
    float3 d = c.forward + (sx * c.tanHalfFovY * c.aspect) * c.right + (sy * c.tanHalfFovY) * c.up;
    RayDifferential rd;
    rd.dPdx = splat3(0.0f);
    rd.dPdy = splat3(0.0f);
    rd.dDdx = normalizeDerivative(d, (2.0f * c.tanHalfFovY * c.aspect / c.width) * c.right);
    rd.dDdy = normalizeDerivative(d, (-2.0f * c.tanHalfFovY / c.height) * c.up);
    return rd;
}

// Transfer over distance t to the plane with normal n through the hit (Igehy eq. 12-13):
//   dt = -(dP + t dD).n / (D.n),  dP' = dP + t dD + dt D,  dD' = dD.
// Afterwards dP lies in the plane, so it can be expressed in the surface's parameters.
CAUSTICS_FN RayDifferential transferRayDifferential(RayDifferential rd, float3 d, float t, float3 n) {
    float dn = dot(d, n);
    float3 px = rd.dPdx + t * rd.dDdx;
    float3 py = rd.dPdy + t * rd.dDdy;
    rd.dPdx = px - (dot(px, n) / dn) * d;
    rd.dPdy = py - (dot(py, n) / dn) * d;
    return rd;
}

// Derivative of the interpolated shading normal N = normalize(nU), nU = n0 + b1 (n1 - n0) + b2 (n2 - n0),
// along a surface displacement dP in the triangle's plane. e1 = p1 - p0, e2 = p2 - p0 (world);
// dn1 = n1 - n0, dn2 = n2 - n0 (world-space vertex normals; the normal matrix is linear, so
// interpolating transformed normals gives the same direction). The barycentric changes come from the
// dual basis of (e1, e2) in the plane: db1 = dP.(e2 x g) / |g|^2, db2 = dP.(g x e1) / |g|^2, g = e1 x e2.
CAUSTICS_FN float3 shadingNormalDerivative(float3 e1, float3 e2, float3 dn1, float3 dn2, float3 nU, float3 dP) {
    float3 g = cross(e1, e2);
    float gg = max(dot(g, g), 1.0e-30f);
    float db1 = dot(dP, cross(e2, g)) / gg;
    float db2 = dot(dP, cross(g, e1)) / gg;
    return normalizeDerivative(nU, db1 * dn1 + db2 * dn2);
}

// Mirror reflection R = D - 2 (D.N) N (Igehy eq. 14-15):
//   dR = dD - 2 ((D.N) dN + d(D.N) N),  d(D.N) = dD.N + D.dN.
CAUSTICS_FN RayDifferential reflectRayDifferential(RayDifferential rd, float3 d, float3 n, float3 dNdx, float3 dNdy) {
    float dn = dot(d, n);
    rd.dDdx = rd.dDdx - 2.0f * (dn * dNdx + (dot(rd.dDdx, n) + dot(d, dNdx)) * n);
    rd.dDdy = rd.dDdy - 2.0f * (dn * dNdy + (dot(rd.dDdy, n) + dot(d, dNdy)) * n);
    return rd;
}

// Refraction T = eta D - mu N with eta = etaI / etaT, N facing the incoming ray (D.N < 0) and
// mu = eta (D.N) - (T.N) (Igehy eq. 16-17):
//   dT = eta dD - (dmu N + mu dN),  dmu = (eta - eta^2 (D.N) / (T.N)) d(D.N).
// t: the refracted unit direction (T.N < 0).
CAUSTICS_FN RayDifferential refractRayDifferential(RayDifferential rd, float3 d, float3 t, float3 n, float eta, float3 dNdx,
                                                   float3 dNdy) {
    float dn = dot(d, n);
    float tn = dot(t, n);
    float mu = eta * dn - tn;
    float dmuScale = eta - eta * eta * dn / tn;
    float dmuX = dmuScale * (dot(rd.dDdx, n) + dot(d, dNdx));
    float dmuY = dmuScale * (dot(rd.dDdy, n) + dot(d, dNdy));
    rd.dDdx = eta * rd.dDdx - (dmuX * n + mu * dNdx);
    rd.dDdy = eta * rd.dDdy - (dmuY * n + mu * dNdy);
    return rd;
}

// The differential of a sampled specular event `ev` (common/specular_event.h) of a ray arriving along
// d at a surface with outward shading normal n, whose derivatives along the transferred dPdx, dPdy
// are dNdx, dNdy. The normal used is the one the event scattered about, recovered from the two
// directions (the half vector for reflection, the generalised half vector etaI d - etaT t for
// refraction: Walter et al. 2007, eq. 16): on smooth surfaces that is n itself; on rough ones the
// sampled microfacet normal, with the macro-surface's derivatives. A thin wall passes the ray
// unbent, so its direction differential is unchanged.
CAUSTICS_FN RayDifferential scatterRayDifferential(RayDifferential rd, float3 d, SpecularEvent ev, float3 n, float3 dNdx,
                                                   float3 dNdy, OpticalMaterial mat) {
    bool entering = dot(d, n) < 0.0f;
    float sideSign = entering ? 1.0f : -1.0f;
    if (ev.kind == kEventReflect) {
        float3 h = ev.direction - d;
        float3 m = dot(h, h) > 1.0e-20f ? normalize(h) : sideSign * n;
        return reflectRayDifferential(rd, d, m, sideSign * dNdx, sideSign * dNdy);
    }
    if (mat.thinWalled) return rd;
    float etaI = entering ? 1.0f : mat.ior;
    float etaT = entering ? mat.ior : 1.0f;
    float3 h = etaI * d - etaT * ev.direction;
    float3 m = dot(h, h) > 1.0e-20f ? normalize(h) : sideSign * n;
    if (dot(m, d) > 0.0f) m = -m;
    return refractRayDifferential(rd, d, ev.direction, m, etaI / etaT, sideSign * dNdx, sideSign * dNdy);
}

// Area of the parallelogram one pixel covers on the surface the differential was transferred to.
CAUSTICS_FN float rayFootprintArea(RayDifferential rd) { return length(cross(rd.dPdx, rd.dPdy)); }

// The parallelogram's longest extent: the larger singular value of [dP/dx dP/dy] (the square root of the
// larger eigenvalue of their Gram matrix, whose determinant is the squared area).
CAUSTICS_FN float rayFootprintMajorAxis(RayDifferential rd) {
    float a = dot(rd.dPdx, rd.dPdx), b = dot(rd.dPdy, rd.dPdy), area = rayFootprintArea(rd);
    float trace = a + b;
    return sqrt(0.5f * (trace + sqrt(max(trace * trace - 4.0f * area * area, 0.0f))));
}

CAUSTICS_SHARED_END

#endif  // CAUSTICS_COMMON_RAY_DIFFERENTIAL_H
