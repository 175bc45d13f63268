// Refusals at the module boundary: a host G-buffer texture the passes cannot use is named with its
// problem (docs/embedding.md "G-buffer").
#include <gtest/gtest.h>

#include "caustics/caustics_module.h"
#include "caustics/scene/gpu_scene.h"
#include "gpu_test.h"
#include "spot_sphere_scene.h"

namespace caustics::test {
namespace {

constexpr uint32_t kSize = 16;

class HostGBufferRefusal : public GpuTest {
protected:
    rhi::TextureHandle texture(rhi::Format f, rhi::TextureUsage usage, const char* name) {
        auto t = device->createTexture(rhi::TextureDesc().setSize(kSize, kSize).setFormat(f).setUsage(usage).setDebugName(name));
        EXPECT_TRUE(t) << t.message();
        return t ? t.value() : nullptr;
    }

    // A caustics-only host G-buffer (filter and second type off: linearDepth and objectId suffice).
    Status addWith(const HostGBuffer& g) {
        scene::Scene scene = spotSphereScene();
        auto gpuScene = scene::GpuScene::create(*device, scene);
        if (!gpuScene) return gpuScene.error();
        CausticsSettings s;
        s.causticsOnly = true;
        s.filter = false;
        s.secondType = false;
        s.mapResolution = 16;
        auto module = CausticsModule::create(device, scene, gpuScene.value(), s);
        if (!module) return module.error();
        rg::RenderGraph graph;
        FrameInputs in;
        in.camera = cameraViewMatrices(spotSphereCamera(), kSize, kSize);
        in.width = in.height = kSize;
        in.hostGBuffer = g;
        auto out = module.value()->addPasses(graph, in);
        if (!out) return out.error();
        return okStatus();
    }
};

// Linear depth and object ids as given: the only channels a caustics-only, unfiltered first-type run reads.
HostGBuffer depthAndIds(rhi::TextureHandle linearDepth, rhi::TextureHandle objectId) {
    HostGBuffer g;
    g.linearDepth = std::move(linearDepth);
    g.objectId = std::move(objectId);
    return g;
}

TEST_F(HostGBufferRefusal, ObjectIdOfTheWrongFormatIsNamedWithBothFormats) {
    Status st = addWith(depthAndIds(texture(rhi::Format::R32_FLOAT, rhi::TextureUsage::Sampled, "host depth"),
                                    texture(rhi::Format::R32_FLOAT, rhi::TextureUsage::Sampled, "host ids")));
    ASSERT_FALSE(st);
    EXPECT_NE(st.message().find("hostGBuffer.objectId"), std::string::npos) << st.message();
    EXPECT_NE(st.message().find("'host ids'"), std::string::npos) << st.message();
    EXPECT_NE(st.message().find("R32_UINT"), std::string::npos) << st.message();
}

TEST_F(HostGBufferRefusal, LinearDepthWithoutSampledUsageIsNamed) {
    Status st = addWith(depthAndIds(texture(rhi::Format::R32_FLOAT, rhi::TextureUsage::Storage, "host depth"),
                                    texture(rhi::Format::R32_UINT, rhi::TextureUsage::Sampled, "host ids")));
    ASSERT_FALSE(st);
    EXPECT_NE(st.message().find("hostGBuffer.linearDepth"), std::string::npos) << st.message();
    EXPECT_NE(st.message().find("Sampled usage"), std::string::npos) << st.message();
}

TEST_F(HostGBufferRefusal, MissingRequiredChannelIsNamed) {
    Status st = addWith(depthAndIds(texture(rhi::Format::R32_FLOAT, rhi::TextureUsage::Sampled, "host depth"), nullptr));
    ASSERT_FALSE(st);
    EXPECT_NE(st.message().find("hostGBuffer.objectId is missing"), std::string::npos) << st.message();
}

// An id map shorter than the count the host states: the id pass would search past its end.
TEST_F(HostGBufferRefusal, ObjectIdMapShorterThanItsCountIsNamedWithBothCounts) {
    HostGBuffer g = depthAndIds(texture(rhi::Format::R32_FLOAT, rhi::TextureUsage::Sampled, "host depth"),
                                texture(rhi::Format::R32_UINT, rhi::TextureUsage::Sampled, "host ids"));
    auto map = device->createBuffer(
        rhi::BufferDesc().setByteSize(3 * 8).setUsage(rhi::BufferUsage::Storage).setDebugName("host id map"));
    ASSERT_TRUE(map) << map.message();
    g.objectIdMap = map.value();
    g.objectIdMapCount = 4;
    Status st = addWith(g);
    ASSERT_FALSE(st);
    EXPECT_NE(st.message().find("hostGBuffer.objectIdMap ('host id map') holds 3 (hostId, moduleId) pairs"),
              std::string::npos) << st.message();
    EXPECT_NE(st.message().find("objectIdMapCount is 4"), std::string::npos) << st.message();
}

TEST_F(HostGBufferRefusal, DepthTextureIsNotRequired) {
    // No depth texture: the module never reads it.
    Status st = addWith(depthAndIds(texture(rhi::Format::R32_FLOAT, rhi::TextureUsage::Sampled, "host depth"),
                                    texture(rhi::Format::R32_UINT, rhi::TextureUsage::Sampled, "host ids")));
    EXPECT_TRUE(st) << st.message();
}

}  // namespace
}  // namespace caustics::test
