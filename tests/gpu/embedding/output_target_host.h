#pragma once
// The host of the output-target tests (docs/embedding.md "Output target"): a caustics-only module fed by
// a host G-buffer (our own G-buffer pass, copied into textures the test owns), and one frame of it into
// a host target the host clears in its own command list first, with the module's RGBA32_FLOAT caustics
// of the same frame copied out beside it. Shared by output_target_test.cpp (formats, states) and
// output_target_contract_test.cpp (display path, refusals).
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <string>
#include <tuple>
#include <vector>

#include "caustics/rhi/log.h"
#include "caustics/scene/gpu_scene.h"
#include "gpu_test.h"
#include "module_frames.h"
#include "spot_sphere_scene.h"

#include <memory>

namespace caustics::test {

inline constexpr uint32_t kTargetSize = 64;   // the images of these tests: 64 x 64
inline constexpr float kHostClear[4] = {0.25f, 0.5f, 0.125f, 0.75f};   // exact in the float formats (unorm: rounded)

inline CausticsSettings causticsOnlySettings() {
    CausticsSettings s;
    s.causticsOnly = true;
    s.mapResolution = 64;
    s.raysPerTexel = 2.0f;   // 8192 photons: a few ms on lavapipe
    s.secondType = false;
    s.filter = false;
    s.maxStoredHits = 1u << 12;
    s.framesInFlight = 1;
    return s;
}

inline float halfToFloat(uint16_t h) {
    const uint32_t e = (h >> 10) & 31u, m = h & 1023u;
    const float mag = e == 0 ? std::ldexp(float(m), -24) : std::ldexp(float(m | 1024u), int(e) - 25);
    return (h & 0x8000u) ? -mag : mag;
}
inline float srgbDecode(float e) { return e <= 0.04045f ? e / 12.92f : std::pow((e + 0.055f) / 1.055f, 2.4f); }
inline float srgbEncode(float l) { return l <= 0.0031308f ? l * 12.92f : 1.055f * std::pow(l, 1.0f / 2.4f) - 0.055f; }

// Texel i of a read-back image, channels RGBA, as the shader sees them (sRGB: still encoded).
inline std::array<float, 4> texel(const std::vector<uint8_t>& bytes, rhi::Format format, size_t i) {
    std::array<float, 4> v{};
    switch (format) {
        case rhi::Format::RGBA32_FLOAT: std::memcpy(v.data(), bytes.data() + 16 * i, 16); break;
        case rhi::Format::RGBA16_FLOAT:
            for (int c = 0; c < 4; ++c) {
                uint16_t h;
                std::memcpy(&h, bytes.data() + 8 * i + 2 * c, 2);
                v[c] = halfToFloat(h);
            }
            break;
        case rhi::Format::BGRA8_UNORM:
            for (int c = 0; c < 4; ++c) v[c] = bytes[4 * i + (c == 3 ? 3 : 2 - c)] / 255.0f;
            break;
        case rhi::Format::RGB10A2_UNORM: {
            uint32_t p;
            std::memcpy(&p, bytes.data() + 4 * i, 4);
            v = {(p & 1023u) / 1023.0f, (p >> 10 & 1023u) / 1023.0f, (p >> 20 & 1023u) / 1023.0f, (p >> 30) / 3.0f};
            break;
        }
        case rhi::Format::R11G11B10_FLOAT: {   // the half's exponent and top mantissa bits, unsigned
            uint32_t p;
            std::memcpy(&p, bytes.data() + 4 * i, 4);
            v = {halfToFloat(uint16_t((p & 0x7FFu) << 4)), halfToFloat(uint16_t((p >> 11 & 0x7FFu) << 4)),
                 halfToFloat(uint16_t((p >> 22) << 5)), 1.0f};   // no alpha: read as 1
            break;
        }
        default:   // RGBA8_UNORM, RGBA8_SRGB
            for (int c = 0; c < 4; ++c) v[c] = bytes[4 * i + c] / 255.0f;
    }
    return v;
}


struct Frame {
    std::vector<uint8_t> target;      // the host target after the frame (its format)
    std::vector<glm::vec4> caustics;  // the module's RGBA32_FLOAT caustics of the same frame
};

class OutputTarget : public GpuTest {
protected:
    void SetUp() override {
        GpuTest::SetUp();
        scene_ = spotSphereScene();
        auto gpuScene = scene::GpuScene::create(*device, scene_);
        ASSERT_TRUE(gpuScene) << gpuScene.message();
        gpuScene_ = std::make_unique<scene::GpuScene>(std::move(gpuScene.value()));
        auto gbuffer = renderHostGBuffer();
        ASSERT_TRUE(gbuffer) << gbuffer.message();
        gbuffer_ = gbuffer.value();
        auto module = CausticsModule::create(device, scene_, *gpuScene_, causticsOnlySettings());
        ASSERT_TRUE(module) << module.message();
        module_ = std::move(module.value());
    }
    void TearDown() override {
        module_.reset();
        GpuTest::TearDown();
    }

    // The host's G-buffer: our own G-buffer pass (a standalone module, caustics off), copied into
    // textures the test owns, as an engine's G-buffer would be.
    Result<HostGBuffer> renderHostGBuffer() {
        CausticsSettings s;
        s.causticsEnabled = false;
        CAUSTICS_TRY(auto standalone, CausticsModule::create(device, scene_, *gpuScene_, s));
        rg::RenderGraph graph;
        FrameInputs in = viewOf(spotSphereCamera(), kTargetSize).inputs;
        CAUSTICS_TRY(FrameOutputs out, standalone->addPasses(graph, in));
        HostGBuffer g;
        const std::tuple<rhi::TextureHandle*, rg::RgTexture, rhi::Format, const char*> channels[] = {
            {&g.normalRoughness, out.gbuffer.normalRoughness, GBufferFormats::kNormalRoughness, "host normalRoughness"},
            {&g.albedoMetallic, out.gbuffer.albedoMetallic, GBufferFormats::kAlbedoMetallic, "host albedoMetallic"},
            {&g.optics, out.gbuffer.optics, GBufferFormats::kOptics, "host optics"},
            {&g.linearDepth, out.gbuffer.linearDepth, GBufferFormats::kLinearDepth, "host linearDepth"},
            {&g.objectId, out.gbuffer.objectId, GBufferFormats::kObjectId, "host objectId"}};
        for (const auto& [handle, source, format, name] : channels) {
            CAUSTICS_TRY(*handle, device->createTexture(rhi::TextureDesc().setSize(kTargetSize, kTargetSize).setFormat(format)
                                                            .setUsage(rhi::TextureUsage::Sampled | rhi::TextureUsage::CopyDest)
                                                            .setDebugName(name)));
            copyInto(graph, source, *handle, rhi::ResourceState::Undefined, rhi::ResourceState::ShaderResource);
        }
        CAUSTICS_TRY(rhi::CommandListHandle cmd, device->createCommandList());
        cmd->begin();
        Status st = graph.execute(*device, *cmd);
        cmd->end();
        CAUSTICS_CHECK(st);
        CAUSTICS_TRY(uint64_t fence, device->submit(cmd));
        CAUSTICS_CHECK(device->waitForFence(fence));
        g.state = rhi::ResourceState::ShaderResource;
        return g;
    }

    // A pass of the host's: copies `source` into its own texture `dst` (imported in `before`, left in `after`).
    static void copyInto(rg::RenderGraph& graph, rg::RgTexture source, const rhi::TextureHandle& dst,
                         rhi::ResourceState before, rhi::ResourceState after) {
        rg::RgTexture imported = graph.importTexture(dst->desc().debugName, dst, before, after);
        graph.addPass("host.copy " + dst->desc().debugName, [&](rg::PassBuilder& b) {
            rg::RgTexture s = b.read(source, rg::Access::CopySource), d = b.write(imported, rg::Access::CopyDest);
            const rhi::TextureRegion all = rhi::TextureRegion().setSize(kTargetSize, kTargetSize);
            return [=](rg::PassContext& ctx) { ctx.cmd().copyTexture(ctx.texture(d), all, ctx.texture(s), all); };
        });
        graph.markOutput(imported);
    }

    // One caustics-only frame: the host clears `target` to kHostClear in its command list, then records
    // the module's graph into the same list, handing the target over in CopyDest; the module's own
    // caustics are copied out of the same graph.
    // handOver RenderTarget: the host clears it with a render pass of its own instead (its lighting pass).
    Result<Frame> frame(const rhi::TextureHandle& target, OutputWrite write, float scale,
                        rhi::ResourceState handOver = rhi::ResourceState::CopyDest) {
        CAUSTICS_TRY(rhi::TextureHandle reference,
                     device->createTexture(rhi::TextureDesc().setSize(kTargetSize, kTargetSize).setFormat(rhi::Format::RGBA32_FLOAT)
                                               .setUsage(rhi::TextureUsage::CopyDest | rhi::TextureUsage::CopySource)
                                               .setDebugName("module caustics")));
        rg::RenderGraph graph;
        FrameInputs in = viewOf(spotSphereCamera(), kTargetSize).inputs;
        in.frameIndex = frameIndex_++;
        in.hostGBuffer = gbuffer_;
        in.outputTarget = target;
        in.outputState = handOver;
        in.outputWrite = write;
        in.outputScale = scale;
        CAUSTICS_TRY(FrameOutputs out, module_->addPasses(graph, in));
        if (out.caustics.valid())
            copyInto(graph, out.caustics, reference, rhi::ResourceState::Undefined, rhi::ResourceState::CopySource);
        CAUSTICS_TRY(rhi::CommandListHandle cmd, device->createCommandList());
        cmd->begin();
        const rhi::TextureBarrier toClear{.texture = target, .before = rhi::ResourceState::Undefined,
                                          .after = handOver};
        cmd->barrier(toClear);
        if (handOver == rhi::ResourceState::RenderTarget) {
            rhi::RenderingDesc pass;
            pass.width = pass.height = kTargetSize;
            rhi::ColorAttachment a;
            a.texture = target;
            a.clear = true;
            std::copy(std::begin(kHostClear), std::end(kHostClear), a.clearValue);
            pass.colors.push_back(a);
            cmd->beginRendering(pass);
            cmd->endRendering();
        } else {
            cmd->clearTextureFloat(target, kHostClear);
        }
        Status st = graph.execute(*device, *cmd);
        cmd->end();
        CAUSTICS_CHECK(st);
        CAUSTICS_TRY(uint64_t fence, device->submit(cmd));
        CAUSTICS_CHECK(device->waitForFence(fence));
        Frame f;
        f.target = readTexture(target, handOver);
        if (out.caustics.valid()) {
            const std::vector<uint8_t> c = readTexture(reference, rhi::ResourceState::CopySource);
            f.caustics.resize(size_t(kTargetSize) * kTargetSize);
            std::memcpy(f.caustics.data(), c.data(), std::min(c.size(), f.caustics.size() * sizeof(glm::vec4)));
        }
        return f;
    }

    Result<rhi::TextureHandle> hostTarget(rhi::Format format, rhi::TextureUsage usage = rhi::TextureUsage::RenderTarget |
                                                                                     rhi::TextureUsage::CopyDest |
                                                                                     rhi::TextureUsage::CopySource,
                                          uint32_t size = kTargetSize) {
        return device->createTexture(rhi::TextureDesc().setSize(size, size).setFormat(format).setUsage(usage)
                                         .setDebugName("host lighting"));
    }

    Status refusal(rhi::Format format, rhi::TextureUsage usage, uint32_t size, float scale = 1.0f) {
        CAUSTICS_TRY(rhi::TextureHandle target, hostTarget(format, usage, size));
        rg::RenderGraph graph;
        FrameInputs in = viewOf(spotSphereCamera(), kTargetSize).inputs;
        in.hostGBuffer = gbuffer_;
        in.outputTarget = target;
        in.outputWrite = OutputWrite::Add;
        in.outputScale = scale;
        CAUSTICS_TRY(FrameOutputs out, module_->addPasses(graph, in));
        (void)out;
        return okStatus();
    }

    scene::Scene scene_;
    std::unique_ptr<scene::GpuScene> gpuScene_;
    HostGBuffer gbuffer_;
    std::unique_ptr<CausticsModule> module_;
    uint32_t frameIndex_ = 0;
};


}  // namespace caustics::test
