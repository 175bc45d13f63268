#ifndef CAUSTICS_COMMON_EMISSION_H
#define CAUSTICS_COMMON_EMISSION_H
// How a light's flux is shared among the texels of its caustic visibility map (docs/caustics.md, "Visibility maps").
// Perspective maps (point, spot): texel (i, j) of an N x N map with half-angle tangent t covers the
// rectangle [x0, x1] x [y0, y1] of the plane z = 1 in the light's frame, x_k = t (2k/N - 1). Its
// solid angle is exact (docs/physics.md, "Texel solid angle"); a photon through it carries
//   Phi = I * falloff * Omega_texel / raysPerTexel        [lm = cd * sr]
// Orthographic maps (directional): a texel is a square of area A on the plane normal to the light,
//   Phi = E * A_texel / raysPerTexel                       [lm = lx * m^2]
#include "common/lang.h"

CAUSTICS_SHARED_BEGIN

// Solid angle of the rectangle [0, x] x [0, y] of the plane z = 1 seen from the origin
// (signed in x and y): atan(x y / sqrt(1 + x^2 + y^2)).
CAUSTICS_FN float planeRectCornerSolidAngle(float x, float y) {
    return atan(x * y / sqrt(1.0f + x * x + y * y));
}

CAUSTICS_FN float planeRectSolidAngle(float x0, float y0, float x1, float y1) {
    return planeRectCornerSolidAngle(x1, y1) - planeRectCornerSolidAngle(x0, y1) -
           planeRectCornerSolidAngle(x1, y0) + planeRectCornerSolidAngle(x0, y0);
}

// Point on the plane z = 1 for continuous texel coordinates (0..N across the map).
CAUSTICS_FN float2 perspectiveMapPlanePoint(float2 texelCoord, float mapSize, float tanHalfAngle) {
    return tanHalfAngle * (2.0f * texelCoord / mapSize - splat2(1.0f));
}

// Solid angle of the planar triangle (a, b, c) on z = 1 seen from the origin (Van Oosterom &
// Strackee 1983): tan(Omega/2) = a.(b x c) / (|a||b||c| + (a.b)|c| + (a.c)|b| + (b.c)|a|). For points on
// z = 1 the triple product equals twice the triangle's area in the plane, computed here from the
// 2D edge vectors, which avoids the cancellation that makes the atan-difference form of
// planeRectSolidAngle lose ~1% per texel in single precision for 512^2 maps.
CAUSTICS_FN float planeTriangleSolidAngle(float2 p0, float2 p1, float2 p2) {
    float3 a = float3(p0.x, p0.y, 1.0f);
    float3 b = float3(p1.x, p1.y, 1.0f);
    float3 c = float3(p2.x, p2.y, 1.0f);
    float2 e1 = p1 - p0;
    float2 e2 = p2 - p0;
    float triple = abs(e1.x * e2.y - e1.y * e2.x);
    float la = length(a);
    float lb = length(b);
    float lc = length(c);
    float denom = la * lb * lc + dot(a, b) * lc + dot(a, c) * lb + dot(b, c) * la;
    return 2.0f * atan2(triple, denom);
}

// Exact solid angle of texel (x, y) of an N x N perspective map: two spherical triangles.
CAUSTICS_FN float perspectiveTexelSolidAngle(uint2 texel, float mapSize, float tanHalfAngle) {
    float2 p0 = perspectiveMapPlanePoint(float2(float(texel.x), float(texel.y)), mapSize, tanHalfAngle);
    float2 p1 = perspectiveMapPlanePoint(float2(float(texel.x + 1u), float(texel.y + 1u)), mapSize, tanHalfAngle);
    float2 p10 = float2(p1.x, p0.y);
    float2 p01 = float2(p0.x, p1.y);
    return planeTriangleSolidAngle(p0, p10, p1) + planeTriangleSolidAngle(p0, p1, p01);
}

// Solid angle of the whole square frustum: 4 atan(t^2 / sqrt(1 + 2 t^2)); 4 pi / 6 for t = 1.
CAUSTICS_FN float perspectiveFrustumSolidAngle(float tanHalfAngle) {
    float t2 = tanHalfAngle * tanHalfAngle;
    return 4.0f * atan(t2 / sqrt(1.0f + 2.0f * t2));
}

// Texel area of an N x N orthographic map covering [-halfExtent, halfExtent]^2.
CAUSTICS_FN float orthographicTexelArea(float halfExtent, float mapSize) {
    float side = 2.0f * halfExtent / mapSize;
    return side * side;
}

// KHR_lights_punctual spot cone attenuation (the extension's recommended smooth falloff):
// s = saturate((cos theta - cos outer) / (cos inner - cos outer)), attenuation = s^2.
CAUSTICS_FN float spotAttenuation(float cosTheta, float cosInner, float cosOuter) {
    float s = saturate((cosTheta - cosOuter) / max(cosInner - cosOuter, 1.0e-4f));
    return s * s;
}

// Total flux of a spot light of intensity I with that falloff:
// 2 pi I [ (1 - cos inner) + (cos inner - cos outer) / 3 ].
CAUSTICS_FN float spotLightFlux(float intensity, float cosInner, float cosOuter) {
    return kTwoPi * intensity * ((1.0f - cosInner) + (cosInner - cosOuter) / 3.0f);
}

// KHR_lights_punctual's recommended range window at distance d from a point or spot light:
// saturate(1 - (d / range)^4)^2; 1 for an infinite range (range <= 0). Direct light multiplies its
// 1/d^2 falloff by it; a caustic deposit at distance d from its light by the same window, so no
// caustic lands beyond the range (docs/caustics.md, "Light range").
CAUSTICS_FN float lightRangeWindow(float distance, float range) {
    if (range <= 0.0f) return 1.0f;
    float r = distance / range;
    float w = saturate(1.0f - r * r * r * r);
    return w * w;
}

CAUSTICS_FN float photonFluxPerspective(float intensity, float texelSolidAngle, float raysPerTexel) {
    return intensity * texelSolidAngle / raysPerTexel;
}

CAUSTICS_FN float photonFluxOrthographic(float illuminance, float texelArea, float raysPerTexel) {
    return illuminance * texelArea / raysPerTexel;
}

CAUSTICS_SHARED_END

#endif  // CAUSTICS_COMMON_EMISSION_H
