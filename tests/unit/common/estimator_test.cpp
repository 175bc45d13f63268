// The light-tracing estimator of shaders/common/camera.h, checked end to end without a ray tracer:
// photons spread uniformly over a uniformly lit Lambertian plane, splatted into an oblique pinhole
// camera, must reproduce the analytic radiance L = rho E / pi in every pixel.
#include <cmath>

#include <gtest/gtest.h>

#include "common/camera.h"
#include "common/rng.h"

namespace sh = caustics::shader;

TEST(LightTracingEstimator, UniformlyLitLambertianPlaneGivesRhoEOverPiInEveryPixel) {
    const float rho = 0.7f, illuminance = 3.0f;  // lux on the plane y = 0
    const uint32_t w = 48, h = 40;
    sh::PinholeCamera cam = sh::makePinholeCamera(glm::vec3(0.4f, 3.0f, 2.5f), glm::vec3(0.0f), glm::vec3(0, 1, 0),
                                                  glm::radians(40.0f), float(w), float(h));
    const glm::vec2 lo(-4.0f, -5.0f), hi(4.5f, 3.0f);  // plane patch (x, z) that contains the view
    for (glm::vec2 corner : {glm::vec2(0, 0), glm::vec2(float(w), 0), glm::vec2(0, float(h)), glm::vec2(float(w), float(h))}) {
        glm::vec3 d = sh::cameraRayDirection(cam, corner);
        ASSERT_LT(d.y, 0.0f);
        glm::vec3 p = cam.eye + d * (-cam.eye.y / d.y);
        ASSERT_TRUE(p.x > lo.x && p.x < hi.x && p.z > lo.y && p.z < hi.y) << "view leaves the lit patch";
    }
    const float area = (hi.x - lo.x) * (hi.y - lo.y);
    const uint64_t photons = 12'000'000;
    const float flux = illuminance * area / float(photons);  // lm per photon
    const glm::vec3 n(0, 1, 0);
    std::vector<double> image(w * h, 0.0);
    sh::Rng rng = sh::rngCreate(11, 0, 0, 0);
    for (uint64_t i = 0; i < photons; ++i) {
        glm::vec2 u = sh::rngNextFloat2(rng);
        glm::vec3 x(lo.x + u.x * (hi.x - lo.x), 0.0f, lo.y + u.y * (hi.y - lo.y));
        sh::CameraProjection p = sh::projectToCamera(cam, x);
        if (!p.valid) continue;
        float cosSurface = glm::dot(n, (cam.eye - x) / p.distance);
        image[uint32_t(p.pixel.y) * w + uint32_t(p.pixel.x)] +=
            flux * (rho / M_PI) * sh::pinholeSplatFactor(cam, p.cosTheta, cosSurface, p.distance);
    }
    const double expected = rho * illuminance / M_PI;
    double sumRel = 0, sumVar = 0;
    for (uint32_t y = 0; y < h; ++y) {
        for (uint32_t x = 0; x < w; ++x) {
            // Expected photon count in the pixel's footprint: lambda = N A_footprint / A_patch with
            // A_footprint = A_pixel cos^3(theta_c) d^2 / cos(theta_s) at the pixel centre. The
            // count is Poisson, so the pixel's relative standard deviation is 1 / sqrt(lambda).
            glm::vec3 d = sh::cameraRayDirection(cam, glm::vec2(x + 0.5f, y + 0.5f));
            float dist = -cam.eye.y / d.y;
            float cosC = glm::dot(d, cam.forward), cosS = -d.y;
            double footprint = sh::pinholePixelArea(cam) * cosC * cosC * cosC * dist * dist / cosS;
            double lambda = double(photons) * footprint / area;
            ASSERT_GT(lambda, 300.0);
            double rel = image[y * w + x] / expected - 1.0;
            // 5 sigma per pixel (1920 pixels: a false alarm has probability ~1e-3 for a correct
            // estimator); a missing cos or distance factor errs by > 10% at the image corners.
            EXPECT_LT(std::abs(rel), 5.0 / std::sqrt(lambda)) << "pixel " << x << "," << y;
            sumRel += rel;
            sumVar += 1.0 / lambda;
        }
    }
    double meanRel = sumRel / (w * h), meanSigma = std::sqrt(sumVar) / (w * h);
    EXPECT_LT(std::abs(meanRel), 4.0 * meanSigma);  // image mean: 4 sigma
}
