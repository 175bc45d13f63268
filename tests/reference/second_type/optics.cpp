// Exact intersections (quadrics and planes) and interface optics; see optics.h.
#include "optics.h"

#include <algorithm>
#include <cmath>

namespace caustics::optics_reference {
namespace {

void keepNearer(SurfaceHit& best, double t, const Vec3& n, double tMin) {
    if (t > tMin && (best.t < 0.0 || t < best.t)) {
        best.t = t;
        best.normal = n;
    }
}

SurfaceHit intersectSphere(const Solid& s, const Vec3& o, const Vec3& d, double tMin) {
    SurfaceHit h;
    Vec3 oc = o - s.centre;
    double b = glm::dot(oc, d);
    double c = glm::dot(oc, oc) - s.radius * s.radius;
    double disc = b * b - c;
    if (disc < 0.0) return h;
    double q = std::sqrt(disc);
    for (double t : {-b - q, -b + q}) keepNearer(h, t, (o + t * d - s.centre) / s.radius, tMin);
    return h;
}

// Slab method in the box's frame.
SurfaceHit intersectBox(const Solid& s, const Vec3& o, const Vec3& d, double tMin) {
    SurfaceHit h;
    Vec3 lo = glm::transpose(s.axes) * (o - s.centre);
    Vec3 ld = glm::transpose(s.axes) * d;
    for (int axis = 0; axis < 3; ++axis) {
        if (std::abs(ld[axis]) < 1e-300) continue;
        for (double sign : {-1.0, 1.0}) {
            double t = (sign * s.halfExtent[axis] - lo[axis]) / ld[axis];
            Vec3 p = lo + t * ld;
            bool inside = true;
            for (int other = 0; other < 3; ++other)
                if (other != axis && std::abs(p[other]) > s.halfExtent[other]) inside = false;
            if (!inside) continue;
            Vec3 n(0.0);
            n[axis] = sign;
            keepNearer(h, t, s.axes * n, tMin);
        }
    }
    return h;
}

SurfaceHit intersectPatches(const Solid& s, const Vec3& o, const Vec3& d, double tMin) {
    SurfaceHit h;
    double ox = o.x - s.centre.x, oz = o.z - s.centre.z;
    for (const Patch& p : s.patches) {
        if (p.kind == Patch::Kind::Side) {
            double a = d.x * d.x + d.z * d.z;
            if (a < 1e-300) continue;
            double b = ox * d.x + oz * d.z;
            double c = ox * ox + oz * oz - p.radius * p.radius;
            double disc = b * b - a * c;
            if (disc < 0.0) continue;
            double q = std::sqrt(disc);
            for (double t : {(-b - q) / a, (-b + q) / a}) {
                double y = o.y + t * d.y;
                if (y < p.yMin || y > p.yMax) continue;
                Vec3 n((ox + t * d.x) / p.radius, 0.0, (oz + t * d.z) / p.radius);
                keepNearer(h, t, p.outwardPositive ? n : -n, tMin);
            }
        } else {
            if (std::abs(d.y) < 1e-300) continue;
            double t = (p.yMin - o.y) / d.y;
            double x = ox + t * d.x, z = oz + t * d.z;
            double r2 = x * x + z * z;
            if (r2 > p.radius * p.radius || r2 < p.rInner * p.rInner) continue;
            keepNearer(h, t, Vec3(0.0, p.outwardPositive ? 1.0 : -1.0, 0.0), tMin);
        }
    }
    return h;
}

}  // namespace

SurfaceHit intersectSolid(const Solid& s, const Vec3& o, const Vec3& d, double tMin) {
    switch (s.kind) {
        case Solid::Kind::Sphere: return intersectSphere(s, o, d, tMin);
        case Solid::Kind::Box: return intersectBox(s, o, d, tMin);
        case Solid::Kind::Patches: return intersectPatches(s, o, d, tMin);
    }
    return {};
}

void dielectricReflectances(double cosI, double n1, double n2, double& rs, double& rp) {
    cosI = std::clamp(cosI, 0.0, 1.0);
    double sinT = n1 / n2 * std::sqrt(std::max(0.0, 1.0 - cosI * cosI));
    rs = rp = 1.0;
    if (sinT >= 1.0) return;
    double cosT = std::sqrt(1.0 - sinT * sinT);
    double as = (n1 * cosI - n2 * cosT) / (n1 * cosI + n2 * cosT);
    double ap = (n1 * cosT - n2 * cosI) / (n1 * cosT + n2 * cosI);
    rs = as * as;
    rp = ap * ap;
}

double dielectricReflectance(double cosI, double n1, double n2) {
    double rs, rp;
    dielectricReflectances(cosI, n1, n2, rs, rp);
    return 0.5 * (rs + rp);
}

bool refracted(const Vec3& d, const Vec3& nFacing, double n1, double n2, Vec3& out) {
    double eta = n1 / n2;
    double cosI = -glm::dot(d, nFacing);
    double k = 1.0 - eta * eta * (1.0 - cosI * cosI);
    if (k <= 0.0) return false;
    out = glm::normalize(eta * d + (eta * cosI - std::sqrt(k)) * nFacing);
    return true;
}

Vec3 conductorReflectance(const Vec3& f0, double cosI) {
    double m = 1.0 - std::clamp(cosI, 0.0, 1.0);
    return f0 + (Vec3(1.0) - f0) * (m * m * m * m * m);
}

double spotFalloff(const Light& l, double cosTheta) {
    if (l.directional) return 1.0;
    double cosOuter = std::cos(l.outerCone), cosInner = std::cos(l.innerCone);
    if (cosTheta <= cosOuter) return 0.0;
    if (cosTheta >= cosInner) return 1.0;
    double x = (cosTheta - cosOuter) / (cosInner - cosOuter);
    return x * x;
}

}  // namespace caustics::optics_reference
