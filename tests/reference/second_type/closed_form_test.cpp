// The independent second-type reference against closed forms: a glass plate between a directional light
// and the floor transmits (1 - R) / (1 + R) (all internal reflections summed, R = ((n-1)/(n+1))^2 at
// normal incidence; Born & Wolf 1.6), with absorption (1 - R)^2 a / (1 - R^2 a^2), a = exp(-sigma d);
// a camera looking down through a second plate sees albedo E T^2 / pi.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>

#include "second_type_estimate.h"

namespace caustics::optics_reference {
namespace {

constexpr double kPi = 3.14159265358979323846;

double slabTransmittance(double ior, double a) {
    double r = std::pow((ior - 1.0) / (ior + 1.0), 2.0);
    return (1.0 - r) * (1.0 - r) * a / (1.0 - r * r * a * a);
}

// A 1 cm plate (2 x 2 m) with its lower face 0.3 m above the floor, light straight down (1 lux).
Scene plateScene(double ior, double sigma) {
    Scene s;
    Object plate;
    plate.solid = boxSolid(Vec3(0.0, 0.305, 0.0), Vec3(1.0, 0.005, 1.0));
    plate.optic.ior = ior;
    plate.optic.sigmaA = Vec3(sigma);
    s.objects.push_back(plate);
    s.light.directional = true;
    s.light.direction = Vec3(0.0, -1.0, 0.0);
    s.light.intensity = 1.0;
    return s;
}

EstimateOptions plateOptions() {
    EstimateOptions o;
    o.photons = 1'000'000;
    o.histogramResolution = 64;
    o.receiverHalfSize = 0.2;
    o.width = o.height = 32;
    o.pathsPerPixel = 16;
    return o;
}

double meanIrradiance(const FloorHistogram& f) {
    Vec3 flux = f.totalFlux();
    return flux.y / (4.0 * f.halfSize * f.halfSize);
}

// ~25,000 photons land in the 0.4 m square (1 M photons over the plate's 2 pi m^2 bounding disk); each
// is transmitted or not, so the mean's relative standard deviation is sqrt((1 - T) / (T N)) = 0.2 %:
// the 1 % bound is 5 sigma.
TEST(IndependentReference, PlateTransmitsOneMinusROverOnePlusR) {
    FloorHistogram f = traceFloorPhotons(plateScene(1.5, 0.0), plateOptions());
    double expected = slabTransmittance(1.5, 1.0);
    std::printf("[ measured ] plate IOR 1.5: floor irradiance %.5f lux (expected %.5f)\n", meanIrradiance(f), expected);
    EXPECT_NEAR(meanIrradiance(f) / expected, 1.0, 0.01);
}

TEST(IndependentReference, AbsorbingPlateFollowsBeerLambert) {
    const double a = 0.6, sigma = -std::log(a) / 0.01;
    FloorHistogram f = traceFloorPhotons(plateScene(1.5, sigma), plateOptions());
    double expected = slabTransmittance(1.5, a);
    std::printf("[ measured ] absorbing plate: floor irradiance %.5f lux (expected %.5f)\n", meanIrradiance(f), expected);
    EXPECT_NEAR(meanIrradiance(f) / expected, 1.0, 0.015);
}

// The camera 1 m above the floor looks straight down through the plate (10 degree field, so the view
// angle stays below 5 degrees, where T changes by < 1e-4): every path reaches the floor under the
// plate, whose caustic irradiance is the plate's T; the image is albedo T^2 / pi. Bound 1.5 %: the
// photon mean (0.2 %) and 16,384 camera paths, each transmitted or not (0.2 %), at 5 sigma.
TEST(IndependentReference, CameraThroughPlateSeesTheFloorTimesTheSquaredTransmittance) {
    Scene s = plateScene(1.5, 0.0);
    EstimateOptions o = plateOptions();
    FloorHistogram f = traceFloorPhotons(s, o);
    Pinhole cam;
    cam.eye = Vec3(0.0, 1.0, 0.0);
    cam.target = Vec3(0.0);
    cam.up = Vec3(0.0, 0.0, -1.0);
    cam.verticalFov = 10.0 * kPi / 180.0;
    SecondTypeImage img = renderSecondType(s, cam, f, o);
    double sum = 0.0;
    for (const Vec3& v : img.radiance) sum += v.y;
    double mean = sum / double(img.radiance.size());
    double t = slabTransmittance(1.5, 1.0);
    double expected = s.floorAlbedo * t * t / kPi;
    std::printf("[ measured ] camera through plate: %.5f cd/m^2 (expected %.5f), %llu paths on the floor\n", mean, expected,
                (unsigned long long)img.pathsOnFloor);
    EXPECT_NEAR(mean / expected, 1.0, 0.015);
}

}  // namespace
}  // namespace caustics::optics_reference
