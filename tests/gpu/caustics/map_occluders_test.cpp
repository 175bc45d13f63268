// CausticsSettings::mapOccluders: a map of the specular objects alone emits from a superset of the
// texels of a map with occluders, and stays unbiased because the forward ray starts at the light and
// ends on the first occluder it meets (docs/caustics.md, "Maps without occluders").
#include <gtest/gtest.h>

#include <cstdio>

#include <glm/gtc/matrix_transform.hpp>

#include "caustic_harness.h"
#include "caustic_test_scene.h"
#include "caustics/scene/builtin_scenes.h"
#include "gpu_test.h"

namespace caustics::test {
namespace {

// A 2 x 2 m glass slab (bottom at y = 1) under a vertical directional light, and a diffuse sheet at
// y = 1.5 that shades the slab's half x < 0 from the light (a copy of the 8 x 8 m floor, scaled).
scene::Scene shadedSlabScene() {
    scene::AnalyticSceneDesc d;
    d.height = 1.0f;
    d.lightDirection = {0.0f, -1.0f, 0.0f};
    scene::Scene sc = scene::makeGlassSlabScene(d);
    scene::Instance sheet = sc.instances[0];   // the diffuse floor
    sheet.transform = glm::scale(glm::translate(glm::mat4(1.0f), glm::vec3(-0.6f, 1.5f, 0.0f)), glm::vec3(0.15f, 1.0f, 0.3f));
    sheet.objectId = uint32_t(sc.instances.size()) + 1;
    sc.instances.push_back(sheet);
    return sc;
}

// Below the slab, looking down at the floor it lights.
scene::Camera underSlabCamera() {
    scene::Camera c;
    c.eye = {0.0f, 0.9f, 0.4f};
    c.target = {0.0f, 0.0f, 0.0f};
    c.verticalFovRadians = glm::radians(60.0f);
    return c;
}

double fluxSum(const std::vector<CausticHit>& hits) {
    double sum = 0.0;
    for (const CausticHit& h : hits) sum += double(h.flux.r) + h.flux.g + h.flux.b;
    return sum;
}

double imageSum(const std::vector<glm::vec3>& image) {
    double sum = 0.0;
    for (const glm::vec3& c : image) sum += double(c.r) + c.g + c.b;
    return sum;
}

class MapOccluders : public GpuTest {};

TEST_F(MapOccluders, WithAndWithoutOccludersTheCausticEnergyIsTheSameAndTheShadedFloorIsDark) {
    const scene::Scene scene = shadedSlabScene();
    CausticsSettings s = smallSettings();
    s.secondType = true;   // the forward pass stores its diffuse hits only for the second type's gather
    s.mapOccluders = true;
    auto with = runCaustics(*device, scene, underSlabCamera(), 64, 64, s);
    s.mapOccluders = false;
    auto without = runCaustics(*device, scene, underSlabCamera(), 64, 64, s);
    ASSERT_TRUE(with) << with.message();
    ASSERT_TRUE(without) << without.message();
    const uint32_t withTexels = with->stats[kStatEmitterTexels], withoutTexels = without->stats[kStatEmitterTexels];
    const double withFlux = fluxSum(with->hits), withoutFlux = fluxSum(without->hits);
    const double withImage = imageSum(with->firstType), withoutImage = imageSum(without->firstType);
    std::printf("[ measured ] emitting texels %u with occluders, %u without; stored hits %zu / %zu; hit flux %.6g / %.6g; "
                "image %.6g / %.6g\n",
                withTexels, withoutTexels, with->hits.size(), without->hits.size(), withFlux, withoutFlux, withImage,
                withoutImage);
    // Without the sheet in the map, the texels it shades emit too (about twice as many)...
    EXPECT_GT(withoutTexels, withTexels + withTexels / 2);
    // ... and their photons end on the sheet: the same photons reach the floor. Each texel's photon
    // has its own random stream (passes/forward_trace/shaders/forward.h), so the stored hits are the
    // same ones; measured 2026-12-01: equal flux and image sums to the last printed digit. Bound:
    // float-atomic summation order of the splats, 1e-5 relative.
    ASSERT_GT(with->hits.size(), 200u);
    EXPECT_EQ(with->hits.size(), without->hits.size());
    EXPECT_NEAR(withoutFlux, withFlux, 1e-6 * withFlux);
    ASSERT_GT(withImage, 0.0);
    EXPECT_NEAR(withoutImage, withImage, 1e-5 * withImage);
    // The floor the sheet shades (x < 0; the slab is struck at normal incidence, so photons go
    // straight down) receives no caustic photon in either setting.
    for (const auto* run : {&with.value(), &without.value()}) {
        uint32_t shaded = 0;
        for (const CausticHit& h : run->hits)
            if (h.objectId == 1 && h.position.x < -0.01f) ++shaded;
        EXPECT_EQ(shaded, 0u);
    }
}

}  // namespace
}  // namespace caustics::test
