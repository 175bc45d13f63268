// Axial position of the ball-lens focus on the GPU: a sweep of receiver-plane distances around the
// paraxial focus f = n R / (2 (n - 1)) (Hecht, Optics, 5th ed., sec. 6.2 "ball lens"). The lateral
// position is checked in caustic_optics_test.cpp; a plane through the focus cannot tell the axial
// position (it crosses the axis at the same point for any focal length), a sweep can: the spot is
// smallest at the focus. Same geometry as the CPU reference's sweep
// (tests/physics/reference_tracer/sphere_physics_test.cpp), whose scene helpers it reuses.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <utility>
#include <vector>

#include <glm/glm.hpp>

#include "caustic_harness.h"
#include "gpu_test.h"
#include "test_scenes.h"

namespace caustics::test {
namespace {

using namespace caustics::physics;

constexpr float kIor = 1.5f, kRadius = 1.0f, kCentreY = 3.0f;
// Paraxial stop: a diffuse annulus above the ball with a hole of radius 0.08 R. Without it the ball's
// strong spherical aberration puts the smallest full-aperture spot far inside f (marginal rays focus
// at ~1.2 R). Photons that hit the stop end there (a diffuse first hit never splats a caustic).
constexpr float kAperture = 0.08f;
constexpr uint32_t kImage = 128;
constexpr float kElevationDeg = 30.0f;   // camera 60 degrees off the lens axis

struct Spot {
    double rms2 = 0.0;       // flux-weighted mean squared distance from the centroid on the plane, R^2
    double flux = 0.0;
    double footprint = 0.0;  // long side of one pixel's footprint at the spot, R
};

scene::Scene stoppedBallLens(float h) {
    scene::Scene s;
    const float floorY = kCentreY - h;
    addObject(s, makeQuadY(floorY, -3.0f, 3.0f, -3.0f, 3.0f), diffuseMaterial(1.0f));
    addObject(s, makeSphere({0.0f, kCentreY, 0.0f}, kRadius, 192, 96), glassMaterial(kIor));
    addObject(s, makeAnnulusY(kCentreY + kRadius + 0.05f, kAperture, 2.0f, 256), diffuseMaterial(0.5f));
    s.lights.push_back(directionalLight({0.0f, -1.0f, 0.0f}, 1.0f));
    // The passes identify surfaces by Instance::objectId with 0 = background (scene.h); the shared
    // helper numbers instances from 0.
    for (size_t i = 0; i < s.instances.size(); ++i) s.instances[i].objectId = uint32_t(i + 1);
    return s;
}

scene::Camera spotCamera(float floorY) {
    const glm::vec3 spot(0.0f, floorY, 0.0f);
    const float e = glm::radians(kElevationDeg);
    scene::Camera cam;
    cam.eye = spot + 2.0f * glm::vec3(std::cos(e), std::sin(e), 0.0f);
    cam.target = spot;
    cam.verticalFovRadians = glm::radians(8.0f);
    return cam;
}

// Flux per pixel = (pi / albedo) L x footprint area (Lambertian receiver of albedo 1).
Spot measureSpot(const std::vector<glm::vec3>& img, const scene::Camera& cam, float floorY) {
    Spot m;
    glm::dvec2 mean(0.0);
    std::vector<std::pair<glm::dvec2, double>> samples;
    forEachPixelOnPlane(cam, kImage, kImage, floorY, [&](uint32_t x, uint32_t y, glm::vec3 p, float area) {
        // The long side: the footprint is stretched by 1/sin(elevation) along the viewing direction.
        if (glm::length(glm::vec2(p.x, p.z)) < 0.01f)
            m.footprint = std::max(m.footprint, std::sqrt(double(area) / std::sin(glm::radians(double(kElevationDeg)))));
        const double w = M_PI * img[size_t(y) * kImage + x].x * area;
        if (w <= 0.0) return;
        samples.push_back({glm::dvec2(p.x, p.z), w});
        m.flux += w;
        mean += w * glm::dvec2(p.x, p.z);
    });
    if (m.flux <= 0.0) return m;
    mean /= m.flux;
    for (const auto& [p, w] : samples) m.rms2 += w * glm::dot(p - mean, p - mean);
    m.rms2 /= m.flux;
    return m;
}

// Least-squares parabola y = c0 + c1 x + c2 x^2 (normal equations); returns (c0, c1, c2).
glm::dvec3 fitParabola(const std::vector<double>& xs, const std::vector<double>& ys) {
    glm::dmat3 a(0.0);
    glm::dvec3 b(0.0);
    for (size_t i = 0; i < xs.size(); ++i) {
        const glm::dvec3 v(1.0, xs[i], xs[i] * xs[i]);
        a += glm::outerProduct(v, v);
        b += v * ys[i];
    }
    return glm::inverse(a) * b;
}

class CausticFocusSweep : public GpuTest {};

// Five receiver distances h = f + {-0.24, -0.12, 0, 0.12, 0.24} R. Each ray's position on the plane is
// linear in h, so the squared RMS spot radius is exactly quadratic in h and a parabola fit gives the
// best-focus distance. Expected: the middle plane (h = f) has the smallest spot, and the fitted
// minimum lies within one pixel footprint (long side, ~0.0044 R) of f. Spherical aberration of the
// 0.08 R stop moves the RMS best focus towards the lens: an exact Snell trace of a perfect ball with
// this stop and these five planes (20k rays, same fit) gives 1.49822 R, i.e. -1.8e-3 R, inside that
// tolerance. Measured on lavapipe: 1.49819 R; RMS radii 0.0091/0.0048/0.0024/0.0049/0.0092 R.
TEST_F(CausticFocusSweep, GlassSphereSpotIsSmallestAtTheParaxialFocus) {
    const double f = kIor * kRadius / (2.0 * (kIor - 1.0));
    const std::vector<double> offsets = {-0.24, -0.12, 0.0, 0.12, 0.24};
    CausticsSettings s;
    // The map covers the ball's bounding sphere (orthographic, half-extent R): the hole spans ~10
    // texels in radius, ~330 texels, x 64 rays = ~21k rays through the stop per plane.
    s.mapResolution = 256;
    s.raysPerTexel = 64.0f;
    s.maxSpecularDepth = 2;   // enter + leave: the focusing paths (as the CPU test)
    s.russianRoulette = false;
    s.secondType = false;
    s.filter = false;
    s.maxStoredHits = 1u << 16;
    std::vector<double> rms2;
    double footprint = 0.0;
    for (double dh : offsets) {
        const float h = float(f + dh), floorY = kCentreY - h;
        scene::Scene scene = stoppedBallLens(h);
        scene::Camera cam = spotCamera(floorY);
        auto run = runCaustics(*device, scene, cam, kImage, kImage, s);
        ASSERT_TRUE(run) << run.message();
        Spot m = measureSpot(run.value().firstType, cam, floorY);
        ASSERT_GT(m.flux, 0.0) << "no caustic on the plane at h = " << h;
        // Flux through the stop x the two-interface Fresnel transmittance on axis (~0.92); 5 % for the
        // faceted rim of the hole and the map's texel quantisation of the emitting area.
        EXPECT_NEAR(m.flux / (M_PI * kAperture * kAperture), 0.92, 0.05) << "h = " << h;
        footprint = std::max(footprint, m.footprint);
        rms2.push_back(m.rms2);
        std::printf("[ measured ] h - f = %+.2f R: RMS spot radius %.5f R, flux / stop flux %.4f\n", dh, std::sqrt(m.rms2),
                    m.flux / (M_PI * kAperture * kAperture));
    }
    size_t smallest = 0;
    for (size_t i = 1; i < rms2.size(); ++i)
        if (rms2[i] < rms2[smallest]) smallest = i;
    EXPECT_EQ(smallest, 2u) << "the spot must be smallest on the plane through the paraxial focus";
    glm::dvec3 c = fitParabola(offsets, rms2);
    ASSERT_GT(c.z, 0.0) << "the spot must grow away from the focus";
    const double best = f - c.y / (2.0 * c.z);
    std::printf("[ measured ] fitted best focus %.5f R, paraxial f %.5f R, difference %+.5f R, footprint %.5f R\n", best, f,
                best - f, footprint);
    ASSERT_GT(footprint, 0.0);
    EXPECT_NEAR(best, f, footprint) << "footprint " << footprint;
}

}  // namespace
}  // namespace caustics::test
