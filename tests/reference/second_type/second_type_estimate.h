#pragma once
// The independent second-type estimate (docs/physics.md, "Independent second-type reference"):
//  1. photons from the light through the analytic solids (Fresnel lobes picked with their probabilities,
//     flux conserved, Beer-Lambert inside) land on the floor after >= 1 specular event and fill a
//     histogram of the floor's caustic irradiance E (lux, bins of side b);
//  2. camera paths jittered inside each pixel follow the specular chain (radiance transport: (n1/n2)^2
//     per refraction) to the floor and read L = albedo E(x) / pi there (bilinear between bin centres);
//     the pixel's value is the mean over its paths.
// Both halves are unbiased for the bin-averaged E; the only bias is the bins' blur, O(b^2 E''), which
// the tests bound by halving b. Shares no code with the module's passes or engine/reference.
#include <cstdint>
#include <vector>

#include "analytic_scene.h"

namespace caustics::optics_reference {

struct FloorHistogram {
    double centreX = 0.0, centreZ = 0.0, halfSize = 1.0;  // the square [cx - h, cx + h] x [cz - h, cz + h]
    uint32_t resolution = 0;
    // Radial: the scene is symmetric about the vertical axis through (cx, cz) and the bins are
    // `resolution` rings of width halfSize / resolution (near the axis, where a ball's caustic has its
    // 1/r spike, the rings are as narrow as far out, and each still receives as many photons).
    bool radial = false;
    std::vector<Vec3> irradiance;                         // lux per bin, row-major in (z, x), or per ring
    double binSize() const { return (radial ? 1.0 : 2.0) * halfSize / resolution; }
    // Bilinear between bin centres (linear between ring centres); 0 outside the square (disk).
    Vec3 lookup(double x, double z) const;
    Vec3 totalFlux() const;                               // sum of E x bin area (lm)
};

struct EstimateOptions {
    uint64_t photons = 4'000'000;
    uint32_t histogramResolution = 512;
    double receiverCentreX = 0.0, receiverCentreZ = 0.0, receiverHalfSize = 1.0;
    bool radialHistogram = false;   // FloorHistogram::radial (only for axially symmetric scenes)
    uint32_t width = 128, height = 128;
    uint32_t pathsPerPixel = 64;
    uint32_t maxEvents = 8;      // specular events per path (photon or camera)
    // Camera paths that reach the floor with no specular event read the histogram too: the image is then
    // the first and second type together (the glass-edge test), else the second type alone.
    bool countDirectPaths = false;
    uint64_t seed = 0;
};

// Caustic irradiance on the floor: light paths with at least one specular event.
FloorHistogram traceFloorPhotons(const Scene& scene, const EstimateOptions& options);

struct SecondTypeImage {
    uint32_t width = 0, height = 0;
    std::vector<Vec3> radiance;   // row 0 = top; cd/m^2
    uint64_t pathsOnFloor = 0;    // camera paths that reached the floor after >= 1 specular event
};

// The unit direction through image point (px, py) (pixels, (0, 0) the top-left corner) of a
// width x height image.
Vec3 pinholeRay(const Pinhole& camera, uint32_t width, uint32_t height, double px, double py);

// The floor point that the ray eye + t d reaches through the solids when every dielectric interface
// refracts (the most probable lobe; conductors reflect): false if it reaches the floor after no event,
// or not at all.
bool refractedFloorPoint(const Scene& scene, const Vec3& eye, const Vec3& d, uint32_t maxEvents, Vec3& point);

// Radiance of the floor's caustic seen through the specular chain, per pixel.
SecondTypeImage renderSecondType(const Scene& scene, const Pinhole& camera, const FloorHistogram& floor,
                                 const EstimateOptions& options);

}  // namespace caustics::optics_reference
