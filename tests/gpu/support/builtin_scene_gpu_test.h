#pragma once
// A GpuTest with the built-in table scene and its GpuScene loaded, for the tests that create a
// CausticsModule on them (memory report, frame memory budget).
#include <optional>

#include "caustics/scene/builtin_scenes.h"
#include "caustics/scene/gpu_scene.h"
#include "gpu_test.h"

namespace caustics::test {

class BuiltinSceneGpuTest : public GpuTest {
protected:
    void SetUp() override {
        GpuTest::SetUp();
        auto built = scene::makeBuiltin("builtin");
        ASSERT_TRUE(built) << built.message();
        scene = std::move(*built);
        auto gpu = scene::GpuScene::create(*device, scene);
        ASSERT_TRUE(gpu) << gpu.message();
        gpuScene.emplace(std::move(*gpu));
    }
    scene::Scene scene;
    std::optional<scene::GpuScene> gpuScene;
};

}  // namespace caustics::test
