// Photon histogram of the floor and camera paths that read it; see second_type_estimate.h and
// docs/physics.md ("Independent second-type reference").
#include "second_type_estimate.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include "optics.h"

namespace caustics::optics_reference {
namespace {

constexpr double kPi = 3.14159265358979323846;
constexpr double kOffset = 1e-9;   // metres: new rays leave a surface on the side they go to

// SplitMix64 (Steele et al. 2014) per path: independent streams from (seed, index).
struct Rng {
    uint64_t state;
    double next() {
        uint64_t z = (state += 0x9E3779B97F4A7C15ull);
        z = (z ^ (z >> 30)) * 0xBF58476D1CE4E5B9ull;
        z = (z ^ (z >> 27)) * 0x94D049BB133111EBull;
        z ^= z >> 31;
        return double(z >> 11) * (1.0 / 9007199254740992.0);
    }
};

Rng pathRng(uint64_t seed, uint64_t stream, uint64_t index) {
    Rng r{seed * 0x2545F4914F6CDD1Dull ^ (stream << 56) ^ (index * 0xD1342543DE82EF95ull)};
    r.next();
    return r;
}

// A thin-walled pane, followed bounce by bounce (no closed form): one polarisation, s or p with
// probability 1/2 (unpolarised light; parallel faces do not mix them), keeps its face reflectance r from
// either side (Stokes r' = -r); the light reflects at the first face, or enters and bounces between the
// faces until it leaves through one of them. True: it leaves on the side it came from.
bool paneReflects(double cosI, double ior, Rng& rng) {
    double rs, rp;
    dielectricReflectances(cosI, 1.0, ior, rs, rp);
    double r = rng.next() < 0.5 ? rs : rp;
    if (rng.next() < r) return true;
    for (;;) {
        if (rng.next() >= r) return false;   // through the far face
        if (rng.next() >= r) return true;    // back out through the near face
    }
}

struct ChainEnd {
    bool onFloor = false;
    Vec3 position{0.0};
    Vec3 weight{0.0};
};

// Follows o + t d through the solids until the floor or a miss. radiance: camera path ((n1/n2)^2 per
// refraction); otherwise a photon (flux conserved). Reaching the floor counts after >= 1 event only.
// refractOnly: every dielectric interface refracts (where it can), instead of picking a Fresnel lobe.
ChainEnd followChain(const Scene& scene, Vec3 o, Vec3 d, bool radiance, uint32_t maxEvents, Rng& rng,
                     bool refractOnly = false, bool direct = false) {
    ChainEnd end;
    Vec3 weight(1.0);
    int inside = -1;   // object whose volume the current segment runs through
    uint32_t events = 0;
    for (;;) {
        double tFloor = (o.y > 0.0 && d.y < 0.0) ? -o.y / d.y : std::numeric_limits<double>::infinity();
        int nearest = -1;
        SurfaceHit hit;
        for (size_t k = 0; k < scene.objects.size(); ++k) {
            SurfaceHit h = intersectSolid(scene.objects[k].solid, o, d, 0.0);
            if (h.t > 0.0 && (nearest < 0 || h.t < hit.t)) {
                hit = h;
                nearest = int(k);
            }
        }
        if (nearest < 0 || tFloor < hit.t) {
            if (std::isfinite(tFloor) && (events > 0 || direct) && inside < 0) {
                end.onFloor = true;
                end.position = o + tFloor * d;
                end.weight = weight;
            }
            return end;
        }
        const Optic& optic = scene.objects[size_t(nearest)].optic;
        if (inside >= 0) {
            const Vec3& s = scene.objects[size_t(inside)].optic.sigmaA;
            weight *= Vec3(std::exp(-s.x * hit.t), std::exp(-s.y * hit.t), std::exp(-s.z * hit.t));
        }
        if (++events > maxEvents) return end;
        Vec3 x = o + hit.t * d;
        bool entering = glm::dot(d, hit.normal) < 0.0;
        Vec3 nFacing = entering ? hit.normal : -hit.normal;
        double cosI = -glm::dot(d, nFacing);
        Vec3 next = d + 2.0 * cosI * nFacing;   // mirror direction
        if (optic.kind == Optic::Kind::Conductor) {
            weight *= conductorReflectance(optic.f0, cosI);
        } else if (optic.thinWalled) {
            if (refractOnly || !paneReflects(cosI, optic.ior, rng)) next = d;   // air on both sides: no (n1/n2)^2
        } else {
            double n1 = entering ? 1.0 : optic.ior, n2 = entering ? optic.ior : 1.0;
            Vec3 t;
            if ((refractOnly || rng.next() >= dielectricReflectance(cosI, n1, n2)) && refracted(d, nFacing, n1, n2, t)) {
                next = t;
                if (radiance) weight *= (n1 / n2) * (n1 / n2);
                inside = entering ? nearest : -1;
            }
        }
        d = next;
        o = x + (glm::dot(d, hit.normal) > 0.0 ? hit.normal : -hit.normal) * kOffset;
    }
}

// Orthonormal frame around unit a.
void frameAround(const Vec3& a, Vec3& u, Vec3& v) {
    u = glm::normalize(std::abs(a.x) < 0.9 ? glm::cross(a, Vec3(1.0, 0.0, 0.0)) : glm::cross(a, Vec3(0.0, 1.0, 0.0)));
    v = glm::cross(a, u);
}

}  // namespace

Vec3 FloorHistogram::lookup(double x, double z) const {
    double b = binSize();
    if (radial) {
        double u = std::hypot(x - centreX, z - centreZ) / b - 0.5;
        if (u > resolution - 0.5) return Vec3(0.0);
        if (u <= 0.0) return irradiance[0];
        size_t i0 = size_t(u);
        double fu = u - double(i0);
        return (1.0 - fu) * irradiance[i0] + fu * irradiance[std::min<size_t>(i0 + 1, resolution - 1)];
    }
    double u = (x - (centreX - halfSize)) / b - 0.5, w = (z - (centreZ - halfSize)) / b - 0.5;
    if (u < -0.5 || w < -0.5 || u > resolution - 0.5 || w > resolution - 0.5) return Vec3(0.0);
    int i0 = int(std::floor(u)), j0 = int(std::floor(w));
    double fu = u - i0, fw = w - j0;
    auto at = [&](int i, int j) {
        i = std::clamp(i, 0, int(resolution) - 1);
        j = std::clamp(j, 0, int(resolution) - 1);
        return irradiance[size_t(j) * resolution + size_t(i)];
    };
    return (1.0 - fw) * ((1.0 - fu) * at(i0, j0) + fu * at(i0 + 1, j0)) + fw * ((1.0 - fu) * at(i0, j0 + 1) + fu * at(i0 + 1, j0 + 1));
}

Vec3 FloorHistogram::totalFlux() const {
    Vec3 sum(0.0);
    for (size_t i = 0; i < irradiance.size(); ++i) sum += irradiance[i] * (radial ? kPi * double(2 * i + 1) : 1.0);
    return sum * binSize() * binSize();
}

FloorHistogram traceFloorPhotons(const Scene& scene, const EstimateOptions& o) {
    FloorHistogram f;
    f.centreX = o.receiverCentreX;
    f.centreZ = o.receiverCentreZ;
    f.halfSize = o.receiverHalfSize;
    f.resolution = o.histogramResolution;
    f.radial = o.radialHistogram;
    f.irradiance.assign(f.radial ? size_t(f.resolution) : size_t(f.resolution) * f.resolution, Vec3(0.0));
    if (scene.objects.empty() || o.photons == 0) return f;

    // Photons aim at the bounding sphere of all solids: light that misses it reaches the floor with no
    // specular event and is no caustic.
    Vec3 lo(1e300), hi(-1e300);
    for (const Object& obj : scene.objects) {
        Vec3 c;
        double r;
        boundingSphere(obj.solid, c, r);
        lo = glm::min(lo, c - Vec3(r));
        hi = glm::max(hi, c + Vec3(r));
    }
    Vec3 centre = 0.5 * (lo + hi);
    double radius = 0.0;
    for (const Object& obj : scene.objects) {
        Vec3 c;
        double r;
        boundingSphere(obj.solid, c, r);
        radius = std::max(radius, glm::length(c - centre) + r);
    }
    // Stratified emission: an M x M grid of jittered cells over the emitter's (a, b) square, whose maps
    // below preserve area (disk) and solid angle (cone), so each cell carries the same flux.
    const uint64_t side = uint64_t(std::floor(std::sqrt(double(o.photons))));
    const uint64_t photons = side * side;
    const Light& light = scene.light;
    Vec3 axis, u, v;
    double cosCone = -1.0, fluxPerPhoton;
    if (light.directional) {
        axis = glm::normalize(light.direction);
        fluxPerPhoton = light.intensity * kPi * radius * radius / double(photons);
    } else {
        Vec3 toCentre = centre - light.position;
        double dist = glm::length(toCentre);
        axis = toCentre / dist;
        if (dist > radius) cosCone = std::sqrt(1.0 - (radius / dist) * (radius / dist));
        fluxPerPhoton = light.intensity * 2.0 * kPi * (1.0 - cosCone) / double(photons);
    }
    frameAround(axis, u, v);

    const double bin = f.binSize(), binArea = bin * bin;
    for (uint64_t k = 0; k < photons; ++k) {
        Rng rng = pathRng(o.seed, 1, k);
        double a = (double(k % side) + rng.next()) / double(side), b = (double(k / side) + rng.next()) / double(side);
        Vec3 origin, dir;
        double flux = fluxPerPhoton;
        if (light.directional) {
            double r = radius * std::sqrt(a), phi = 2.0 * kPi * b;
            origin = centre + r * (std::cos(phi) * u + std::sin(phi) * v) - (2.0 * radius + 10.0) * axis;
            dir = axis;
        } else {
            double cosT = 1.0 - a * (1.0 - cosCone), sinT = std::sqrt(std::max(0.0, 1.0 - cosT * cosT)), phi = 2.0 * kPi * b;
            dir = glm::normalize(cosT * axis + sinT * (std::cos(phi) * u + std::sin(phi) * v));
            origin = light.position;
            flux *= spotFalloff(light, glm::dot(dir, glm::normalize(light.direction)));
            if (flux <= 0.0) continue;
        }
        ChainEnd end = followChain(scene, origin, dir, false, o.maxEvents, rng);
        if (!end.onFloor) continue;
        if (f.radial) {
            size_t ring = size_t(std::hypot(end.position.x - f.centreX, end.position.z - f.centreZ) / bin);
            if (ring < f.resolution) f.irradiance[ring] += end.weight * (flux / (kPi * double(2 * ring + 1) * binArea));
            continue;
        }
        double i = (end.position.x - (f.centreX - f.halfSize)) / bin, j = (end.position.z - (f.centreZ - f.halfSize)) / bin;
        if (i < 0.0 || j < 0.0 || i >= f.resolution || j >= f.resolution) continue;
        f.irradiance[size_t(j) * f.resolution + size_t(i)] += end.weight * (flux / binArea);
    }
    return f;
}

Vec3 pinholeRay(const Pinhole& c, uint32_t width, uint32_t height, double px, double py) {
    Vec3 forward = glm::normalize(c.target - c.eye);
    Vec3 right = glm::normalize(glm::cross(forward, c.up));
    Vec3 up = glm::cross(right, forward);
    double tanHalf = std::tan(0.5 * c.verticalFov), aspect = double(width) / double(height);
    double sx = 2.0 * px / width - 1.0, sy = 1.0 - 2.0 * py / height;
    return glm::normalize(forward + (sx * tanHalf * aspect) * right + (sy * tanHalf) * up);
}

bool refractedFloorPoint(const Scene& scene, const Vec3& eye, const Vec3& d, uint32_t maxEvents, Vec3& point) {
    Rng unused{0};
    ChainEnd end = followChain(scene, eye, d, true, maxEvents, unused, true);
    point = end.position;
    return end.onFloor;
}

SecondTypeImage renderSecondType(const Scene& scene, const Pinhole& c, const FloorHistogram& floor, const EstimateOptions& o) {
    SecondTypeImage img;
    img.width = o.width;
    img.height = o.height;
    img.radiance.assign(size_t(o.width) * o.height, Vec3(0.0));
    for (uint32_t y = 0; y < o.height; ++y)
        for (uint32_t x = 0; x < o.width; ++x) {
            Vec3 sum(0.0);
            for (uint32_t s = 0; s < o.pathsPerPixel; ++s) {
                Rng rng = pathRng(o.seed, 2, (uint64_t(y) * o.width + x) * o.pathsPerPixel + s);
                Vec3 d = pinholeRay(c, o.width, o.height, x + rng.next(), y + rng.next());
                ChainEnd end = followChain(scene, c.eye, d, true, o.maxEvents, rng, false, o.countDirectPaths);
                if (!end.onFloor) continue;
                ++img.pathsOnFloor;
                sum += end.weight * (scene.floorAlbedo / kPi) * floor.lookup(end.position.x, end.position.z);
            }
            img.radiance[size_t(y) * o.width + x] = sum / double(o.pathsPerPixel);
        }
    return img;
}

}  // namespace caustics::optics_reference
