#pragma once
// Ray-solid intersection and interface optics of the independent second-type reference, in double
// precision (docs/physics.md, "Independent second-type reference"). Written apart from the module's
// shaders/common/*.h on purpose: an error shared by the GPU passes and engine/reference cannot hide here.
#include "analytic_scene.h"

namespace caustics::optics_reference {

struct SurfaceHit {
    double t = -1.0;     // < 0: no hit
    Vec3 normal{0.0};    // outward unit normal of the solid at the hit
};

// Nearest hit of the ray o + t d (|d| = 1) with the solid's boundary for t > tMin.
SurfaceHit intersectSolid(const Solid& s, const Vec3& o, const Vec3& d, double tMin);

// s- and p-polarised Fresnel power reflectances of a smooth dielectric interface (Born & Wolf sec.
// 1.5.2): cosI on the incident side, n1 incident and n2 transmitted index; both 1 under total internal
// reflection.
void dielectricReflectances(double cosI, double n1, double n2, double& rs, double& rp);

// Their mean, the unpolarised reflectance.
double dielectricReflectance(double cosI, double n1, double n2);

// Refracted unit direction for unit d arriving at a surface with unit normal nFacing (dot(d, nFacing)
// < 0) from index n1 into n2; false under total internal reflection.
bool refracted(const Vec3& d, const Vec3& nFacing, double n1, double n2, Vec3& out);

// glTF 2.0 Appendix B's conductor Fresnel, F0 + (1 - F0)(1 - cos)^5 (the spec defines metals so).
Vec3 conductorReflectance(const Vec3& f0, double cosI);

// KHR_lights_punctual spot falloff: smoothstep-free square ramp between the cone angles.
double spotFalloff(const Light& l, double cosTheta);

}  // namespace caustics::optics_reference
