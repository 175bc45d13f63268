// Caustics-only output into the host's own target (docs/embedding.md "Output target"): for every format
// causticsOutputFormatSupported() accepts, Replace and Add (onto a host clear colour) give the module's
// own RGBA32_FLOAT caustics of the same frame, read back beside it, within the format's precision; the
// refusals name the field, the format and what is needed. The host clears its target in its own command
// list and hands it over in CopyDest, so the module's barrier must order its draw after the clear
// (synchronization validation is on).
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

namespace caustics::test {
namespace {

constexpr uint32_t kSize = 64;
constexpr float kHostClear[4] = {0.25f, 0.5f, 0.125f, 0.75f};   // exact in the float formats (unorm: rounded)

CausticsSettings causticsOnlySettings() {
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

float halfToFloat(uint16_t h) {
    const uint32_t e = (h >> 10) & 31u, m = h & 1023u;
    const float mag = e == 0 ? std::ldexp(float(m), -24) : std::ldexp(float(m | 1024u), int(e) - 25);
    return (h & 0x8000u) ? -mag : mag;
}
float srgbDecode(float e) { return e <= 0.04045f ? e / 12.92f : std::pow((e + 0.055f) / 1.055f, 2.4f); }
float srgbEncode(float l) { return l <= 0.0031308f ? l * 12.92f : 1.055f * std::pow(l, 1.0f / 2.4f) - 0.055f; }

// Texel i of a read-back image, channels RGBA, as the shader sees them (sRGB: still encoded).
std::array<float, 4> texel(const std::vector<uint8_t>& bytes, rhi::Format format, size_t i) {
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

// What the target holds after the write: Replace stores the value, Add the host's value plus it, each
// converted as the hardware does (unorm clamps to [0, 1]; sRGB blends in linear and encodes). `host` is
// the linear clear value: an 8-bit target holds it rounded to a step (of its sRGB encoding), and the
// blend reads that stored value back (decoded).
// Steps of a unorm channel (0: a float channel): 8-bit 255, RGB10A2 1023 for colour and 3 for alpha.
float unormSteps(rhi::Format format, int channel) {
    switch (format) {
        case rhi::Format::RGBA8_UNORM: case rhi::Format::RGBA8_SRGB: case rhi::Format::BGRA8_UNORM: return 255.0f;
        case rhi::Format::RGB10A2_UNORM: return channel == 3 ? 3.0f : 1023.0f;
        default: return 0.0f;
    }
}

float expectedStored(rhi::Format format, int channel, float value, float host, bool add) {
    const bool srgb = format == rhi::Format::RGBA8_SRGB && channel < 3;
    const float steps = unormSteps(format, channel);
    const bool unorm = steps > 0.0f;
    if (unorm) {
        const float stored = std::round((srgb ? srgbEncode(host) : host) * steps) / steps;
        host = srgb ? srgbDecode(stored) : stored;
    }
    float linear = (add ? host : 0.0f) + value;
    if (unorm) linear = std::clamp(linear, 0.0f, 1.0f);
    return srgb ? srgbEncode(linear) : linear;
}

// The error allowed between a stored value and expectedStored, from the format's precision. Vulkan
// leaves the rounding of float -> unorm and float -> small-float conversions to the implementation
// (nearest: half a step; toward zero: under one), so the bound is one step (ulp) of the stored value:
//  - RGBA32_FLOAT: the float product radiance x scale and one float add: 2 ulp (2^-22 relative);
//  - RGBA16_FLOAT: one ulp of a half, 2^-10 relative (the host's clear value is exact in half, the
//    blend rounds once), plus the smallest half normal (6.1e-5) for values in the subnormal range;
//  - R11G11B10_FLOAT: the same with 6 mantissa bits (red, green: 2^-6 relative) and 5 (blue: 2^-5);
//  - 8-bit unorm and sRGB: one step, 1/255 (sRGB compared encoded, as stored);
//  - RGB10A2_UNORM: one step, 1/1023 (alpha: 1/3).
// Measured on lavapipe: 0 (RGBA32_FLOAT), 0.50 (8-bit unorm), 0.65-0.85 (sRGB), 0.59-0.88 (RGBA16_FLOAT),
// 0.84-0.97 (R11G11B10_FLOAT), 0.84-0.98 (RGB10A2_UNORM) of the bound: it rounds some of these toward zero.
float tolerance(rhi::Format format, int channel, float expected) {
    switch (format) {
        case rhi::Format::RGBA32_FLOAT: return std::ldexp(std::abs(expected), -22) + 1e-30f;
        case rhi::Format::RGBA16_FLOAT: return std::ldexp(std::abs(expected), -10) + 6.1e-5f;
        case rhi::Format::R11G11B10_FLOAT: return std::ldexp(std::abs(expected), channel == 2 ? -5 : -6) + 6.1e-5f;
        default: return 1.0f / unormSteps(format, channel);
    }
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
        FrameInputs in = viewOf(spotSphereCamera(), kSize).inputs;
        CAUSTICS_TRY(FrameOutputs out, standalone->addPasses(graph, in));
        HostGBuffer g;
        const std::tuple<rhi::TextureHandle*, rg::RgTexture, rhi::Format, const char*> channels[] = {
            {&g.normalRoughness, out.gbuffer.normalRoughness, GBufferFormats::kNormalRoughness, "host normalRoughness"},
            {&g.albedoMetallic, out.gbuffer.albedoMetallic, GBufferFormats::kAlbedoMetallic, "host albedoMetallic"},
            {&g.optics, out.gbuffer.optics, GBufferFormats::kOptics, "host optics"},
            {&g.linearDepth, out.gbuffer.linearDepth, GBufferFormats::kLinearDepth, "host linearDepth"},
            {&g.objectId, out.gbuffer.objectId, GBufferFormats::kObjectId, "host objectId"}};
        for (const auto& [handle, source, format, name] : channels) {
            CAUSTICS_TRY(*handle, device->createTexture(rhi::TextureDesc().setSize(kSize, kSize).setFormat(format)
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
            const rhi::TextureRegion all = rhi::TextureRegion().setSize(kSize, kSize);
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
                     device->createTexture(rhi::TextureDesc().setSize(kSize, kSize).setFormat(rhi::Format::RGBA32_FLOAT)
                                               .setUsage(rhi::TextureUsage::CopyDest | rhi::TextureUsage::CopySource)
                                               .setDebugName("module caustics")));
        rg::RenderGraph graph;
        FrameInputs in = viewOf(spotSphereCamera(), kSize).inputs;
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
            pass.width = pass.height = kSize;
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
            f.caustics.resize(size_t(kSize) * kSize);
            std::memcpy(f.caustics.data(), c.data(), std::min(c.size(), f.caustics.size() * sizeof(glm::vec4)));
        }
        return f;
    }

    Result<rhi::TextureHandle> hostTarget(rhi::Format format, rhi::TextureUsage usage = rhi::TextureUsage::RenderTarget |
                                                                                     rhi::TextureUsage::CopyDest |
                                                                                     rhi::TextureUsage::CopySource,
                                          uint32_t size = kSize) {
        return device->createTexture(rhi::TextureDesc().setSize(size, size).setFormat(format).setUsage(usage)
                                         .setDebugName("host lighting"));
    }

    Status refusal(rhi::Format format, rhi::TextureUsage usage, uint32_t size, float scale = 1.0f) {
        CAUSTICS_TRY(rhi::TextureHandle target, hostTarget(format, usage, size));
        rg::RenderGraph graph;
        FrameInputs in = viewOf(spotSphereCamera(), kSize).inputs;
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

using FormatAndWrite = std::tuple<rhi::Format, OutputWrite>;
class OutputTargetFormat : public OutputTarget, public ::testing::WithParamInterface<FormatAndWrite> {};

// The scale puts the brightest caustic pixel at 0.8 (a calibration frame into RGBA32_FLOAT), so that
// unorm targets hold it unclamped and the Add onto 0.5 clamps the brightest pixels (tested as clamped).
TEST_P(OutputTargetFormat, CausticsOnlyOutputEqualsTheModulesCausticsWithinTheFormatsPrecision) {
    const auto [format, write] = GetParam();
    const bool add = write == OutputWrite::Add;
    auto calibration = hostTarget(rhi::Format::RGBA32_FLOAT);
    ASSERT_TRUE(calibration) << calibration.message();
    auto first = frame(calibration.value(), OutputWrite::Replace, 1.0f);
    ASSERT_TRUE(first) << first.message();
    float peak = 0.0f;
    for (const glm::vec4& c : first.value().caustics) peak = std::max({peak, c.r, c.g, c.b});
    ASSERT_GT(peak, 0.0f) << "no caustic in the image";
    const float scale = 0.8f / peak;

    auto target = hostTarget(format);
    ASSERT_TRUE(target) << target.message();
    auto f = frame(target.value(), write, scale);
    ASSERT_TRUE(f) << f.message();
    double worst = 0.0;   // in units of the tolerance
    size_t lit = 0, bad = 0;
    const std::vector<uint8_t>& stored = f.value().target;
    for (size_t i = 0; i < f.value().caustics.size(); ++i) {
        const glm::vec4 c = f.value().caustics[i];
        const std::array<float, 4> got = texel(stored, format, i);
        if (std::max({c.r, c.g, c.b}) > 0.0f) ++lit;
        for (int ch = 0; ch < 4; ++ch) {
            // Alpha: Replace writes 1, Add keeps the host's (R11G11B10_FLOAT has none: read as 1).
            const float expected = format == rhi::Format::R11G11B10_FLOAT && ch == 3 ? 1.0f
                                   : ch == 3 ? expectedStored(format, ch, add ? 0.0f : 1.0f, kHostClear[3], add)
                                             : expectedStored(format, ch, c[ch] * scale, kHostClear[ch], add);
            const float tol = tolerance(format, ch, expected);
            const double err = std::abs(double(got[ch]) - expected);
            worst = std::max(worst, err / tol);
            if (err > tol && ++bad <= 5)
                ADD_FAILURE() << "pixel " << i << " channel " << ch << ": stored " << got[ch] << ", expected " << expected
                              << " (caustics " << c[ch] << " x " << scale << ", tolerance " << tol << ")";
        }
    }
    std::printf("[ measured ] %s %s: %zu lit pixels, worst error %.3g of the tolerance\n", rhi::formatInfo(format).name,
                outputWriteName(write), lit, worst);
    EXPECT_GT(lit, size_t(kSize));   // a caustic, not a black frame compared with a black frame
    EXPECT_EQ(bad, 0u);
}

const FormatAndWrite kFormatsAndWrites[] = {
    {rhi::Format::RGBA8_UNORM, OutputWrite::Replace},  {rhi::Format::RGBA8_UNORM, OutputWrite::Add},
    {rhi::Format::RGBA8_SRGB, OutputWrite::Replace},   {rhi::Format::RGBA8_SRGB, OutputWrite::Add},
    {rhi::Format::BGRA8_UNORM, OutputWrite::Replace},  {rhi::Format::BGRA8_UNORM, OutputWrite::Add},
    {rhi::Format::RGBA16_FLOAT, OutputWrite::Replace}, {rhi::Format::RGBA16_FLOAT, OutputWrite::Add},
    {rhi::Format::RGBA32_FLOAT, OutputWrite::Replace}, {rhi::Format::RGBA32_FLOAT, OutputWrite::Add},
    {rhi::Format::R11G11B10_FLOAT, OutputWrite::Replace}, {rhi::Format::R11G11B10_FLOAT, OutputWrite::Add},
    {rhi::Format::RGB10A2_UNORM, OutputWrite::Replace}, {rhi::Format::RGB10A2_UNORM, OutputWrite::Add},
};

INSTANTIATE_TEST_SUITE_P(EveryFormat, OutputTargetFormat, ::testing::ValuesIn(kFormatsAndWrites),
                         [](const ::testing::TestParamInfo<FormatAndWrite>& info) {
                             return std::string(rhi::formatInfo(std::get<0>(info.param)).name) + "_" +
                                    outputWriteName(std::get<1>(info.param));
                         });

// Every format the RHI offers is either tested above or refused by name.
TEST(OutputTargetFormats, EverySupportedFormatIsTestedAndNoOther) {
    int supported = 0;
    for (uint32_t f = 0; f <= uint32_t(rhi::kLastFormat); ++f) {
        const rhi::Format format = rhi::Format(f);
        const bool tested = std::any_of(std::begin(kFormatsAndWrites), std::end(kFormatsAndWrites),
                                        [&](const FormatAndWrite& p) { return std::get<0>(p) == format; });
        EXPECT_EQ(causticsOutputFormatSupported(format), tested) << rhi::formatInfo(format).name;
        supported += causticsOutputFormatSupported(format) ? 1 : 0;
    }
    EXPECT_EQ(supported, 7);
}

// The usual host: its lighting pass leaves the target a colour attachment (RenderTarget) in the same
// command buffer, and the module adds onto it. The graph's barrier orders the blend after the host's
// render pass (synchronization validation is on); RGBA32_FLOAT: host + caustics x scale within 2 ulp.
TEST_F(OutputTarget, AddAfterTheHostsOwnRenderPassInRenderTargetState) {
    auto target = hostTarget(rhi::Format::RGBA32_FLOAT);
    ASSERT_TRUE(target) << target.message();
    auto f = frame(target.value(), OutputWrite::Add, 2.0f, rhi::ResourceState::RenderTarget);
    ASSERT_TRUE(f) << f.message();
    size_t bad = 0;
    for (size_t i = 0; i < f.value().caustics.size(); ++i)
        for (int ch = 0; ch < 4; ++ch) {
            const float expected = kHostClear[ch] + (ch == 3 ? 0.0f : f.value().caustics[i][ch] * 2.0f);
            const float got = texel(f.value().target, rhi::Format::RGBA32_FLOAT, i)[ch];
            bad += std::abs(got - expected) > tolerance(rhi::Format::RGBA32_FLOAT, ch, expected) ? 1 : 0;
        }
    EXPECT_EQ(bad, 0u);
}

// Caustics switched off (or no light): Replace leaves zero radiance (alpha 1), Add leaves the host's
// image as it was. RGBA16_FLOAT holds kHostClear exactly, so both compare exactly.
TEST_F(OutputTarget, WithoutCausticsReplaceClearsTheTargetAndAddLeavesIt) {
    CausticsSettings off = causticsOnlySettings();
    off.causticsEnabled = false;
    ASSERT_TRUE(module_->setSettings(off).ok());
    auto target = hostTarget(rhi::Format::RGBA16_FLOAT);
    ASSERT_TRUE(target) << target.message();
    for (OutputWrite write : {OutputWrite::Replace, OutputWrite::Add}) {
        auto f = frame(target.value(), write, 1.0f);
        ASSERT_TRUE(f) << f.message();
        size_t differing = 0;
        for (size_t i = 0; i < size_t(kSize) * kSize; ++i) {
            const std::array<float, 4> got = texel(f.value().target, rhi::Format::RGBA16_FLOAT, i);
            for (int ch = 0; ch < 4; ++ch) {
                const float expected = write == OutputWrite::Add ? kHostClear[ch] : (ch == 3 ? 1.0f : 0.0f);
                differing += got[ch] != expected ? 1 : 0;
            }
        }
        EXPECT_EQ(differing, 0u) << outputWriteName(write);
    }
}

// Outside caustics-only mode the target takes the display image (RGBA8_UNORM, Storage). The host need
// not mark it as an output: the module keeps the passes that write it (they used to be culled without
// a word, the target left as it was). Same frame, same seed: the bytes equal the display transient's.
TEST_F(OutputTarget, DisplayIntoHostTargetEqualsTheDisplayImageWithoutMarkingIt) {
    CausticsSettings s;
    s.causticsEnabled = false;   // direct light alone: the display path is what is tested
    auto standalone = CausticsModule::create(device, scene_, *gpuScene_, s);
    ASSERT_TRUE(standalone) << standalone.message();
    auto run = [&](const rhi::TextureHandle& target, const rhi::TextureHandle& copy) -> Status {
        rg::RenderGraph graph;
        FrameInputs in = viewOf(spotSphereCamera(), kSize).inputs;
        in.outputTarget = target;
        in.outputState = rhi::ResourceState::CopySource;
        CAUSTICS_TRY(FrameOutputs out, standalone.value()->addPasses(graph, in));
        if (copy) copyInto(graph, out.display, copy, rhi::ResourceState::Undefined, rhi::ResourceState::CopySource);
        CAUSTICS_TRY(rhi::CommandListHandle cmd, device->createCommandList());
        cmd->begin();
        if (target) {
            const rhi::TextureBarrier toClear{.texture = target, .before = rhi::ResourceState::Undefined,
                                              .after = rhi::ResourceState::CopyDest};
            cmd->barrier(toClear);
            cmd->clearTextureFloat(target, kHostClear);
            const rhi::TextureBarrier toSource{.texture = target, .before = rhi::ResourceState::CopyDest,
                                               .after = rhi::ResourceState::CopySource};
            cmd->barrier(toSource);
        }
        Status st = graph.execute(*device, *cmd);
        cmd->end();
        CAUSTICS_CHECK(st);
        CAUSTICS_TRY(uint64_t fence, device->submit(cmd));
        return device->waitForFence(fence);
    };
    const rhi::TextureUsage usage = rhi::TextureUsage::Storage | rhi::TextureUsage::CopyDest | rhi::TextureUsage::CopySource;
    auto display = hostTarget(rhi::Format::RGBA8_UNORM, rhi::TextureUsage::CopyDest | rhi::TextureUsage::CopySource);
    auto target = hostTarget(rhi::Format::RGBA8_UNORM, usage);
    ASSERT_TRUE(display && target);
    ASSERT_TRUE(run(nullptr, display.value()).ok());
    Status st = run(target.value(), nullptr);
    ASSERT_TRUE(st.ok()) << st.message();
    const std::vector<uint8_t> expected = readTexture(display.value(), rhi::ResourceState::CopySource);
    const std::vector<uint8_t> got = readTexture(target.value(), rhi::ResourceState::CopySource);
    ASSERT_EQ(got.size(), expected.size());
    size_t differing = 0;
    for (size_t i = 0; i < got.size(); ++i) differing += got[i] != expected[i] ? 1 : 0;
    EXPECT_EQ(differing, 0u);
}

// The display path stores RGBA8 through a storage image and replaces the target: another format, or
// Add, is refused naming what it needs and where the other formats go.
TEST_F(OutputTarget, DisplayPathRefusesOtherFormatsAndAdd) {
    CausticsSettings s;
    s.causticsEnabled = false;
    auto standalone = CausticsModule::create(device, scene_, *gpuScene_, s);
    ASSERT_TRUE(standalone) << standalone.message();
    auto attempt = [&](rhi::Format format, OutputWrite write) -> Status {
        CAUSTICS_TRY(rhi::TextureHandle target, hostTarget(format, rhi::TextureUsage::Storage | rhi::TextureUsage::RenderTarget));
        rg::RenderGraph graph;
        FrameInputs in = viewOf(spotSphereCamera(), kSize).inputs;
        in.outputTarget = target;
        in.outputWrite = write;
        CAUSTICS_TRY(FrameOutputs out, standalone.value()->addPasses(graph, in));
        (void)out;
        return okStatus();
    };
    Status half = attempt(rhi::Format::RGBA16_FLOAT, OutputWrite::Replace);
    ASSERT_FALSE(half.ok());
    EXPECT_NE(half.message().find("outputTarget 'host lighting' (RGBA16_FLOAT, 64x64)"), std::string::npos) << half.message();
    EXPECT_NE(half.message().find("RGBA8_UNORM with Storage usage"), std::string::npos) << half.message();
    EXPECT_NE(half.message().find("settings.causticsOnly"), std::string::npos) << half.message();
    Status add = attempt(rhi::Format::RGBA8_UNORM, OutputWrite::Add);
    ASSERT_FALSE(add.ok());
    EXPECT_NE(add.message().find("outputWrite Add"), std::string::npos) << add.message();
}

TEST_F(OutputTarget, IntegerFormatIsRefusedNamingTheFieldTheFormatAndWhatIsNeeded) {
    Status st = refusal(rhi::Format::RGBA32_UINT, rhi::TextureUsage::RenderTarget, kSize);
    ASSERT_FALSE(st.ok());
    for (const char* part : {"outputTarget 'host lighting'", "RGBA32_UINT", "integer", "float or unorm colour format"})
        EXPECT_NE(st.message().find(part), std::string::npos) << part << " in: " << st.message();
}

TEST_F(OutputTarget, DepthFormatIsRefused) {
    Status st = refusal(rhi::Format::D32_FLOAT, rhi::TextureUsage::DepthStencil, kSize);
    ASSERT_FALSE(st.ok());
    EXPECT_NE(st.message().find("D32_FLOAT"), std::string::npos) << st.message();
    EXPECT_NE(st.message().find("depth format"), std::string::npos) << st.message();
}

TEST_F(OutputTarget, TwoChannelFormatIsRefusedRatherThanDroppingBlue) {
    Status st = refusal(rhi::Format::RG16_FLOAT, rhi::TextureUsage::RenderTarget, kSize);
    ASSERT_FALSE(st.ok());
    EXPECT_NE(st.message().find("RG16_FLOAT"), std::string::npos) << st.message();
    EXPECT_NE(st.message().find("fewer than three channels"), std::string::npos) << st.message();
}

TEST_F(OutputTarget, TargetWithoutRenderTargetUsageIsRefused) {
    Status st = refusal(rhi::Format::RGBA16_FLOAT, rhi::TextureUsage::Storage | rhi::TextureUsage::Sampled, kSize);
    ASSERT_FALSE(st.ok());
    EXPECT_NE(st.message().find("RGBA16_FLOAT"), std::string::npos) << st.message();
    EXPECT_NE(st.message().find("lacks RenderTarget usage"), std::string::npos) << st.message();
}

TEST_F(OutputTarget, TargetOfAnotherSizeIsRefusedWithBothSizes) {
    Status st = refusal(rhi::Format::RGBA16_FLOAT, rhi::TextureUsage::RenderTarget, kSize / 2);
    ASSERT_FALSE(st.ok());
    EXPECT_NE(st.message().find("is 32x32, the image (FrameInputs::width x height) is 64x64"), std::string::npos)
        << st.message();
}

TEST_F(OutputTarget, NegativeOrNonFiniteScaleIsRefused) {
    for (float scale : {-1.0f, std::nanf("")}) {
        Status st = refusal(rhi::Format::RGBA16_FLOAT, rhi::TextureUsage::RenderTarget, kSize, scale);
        ASSERT_FALSE(st.ok());
        EXPECT_NE(st.message().find("outputScale"), std::string::npos) << st.message();
    }
}

}  // namespace
}  // namespace caustics::test
