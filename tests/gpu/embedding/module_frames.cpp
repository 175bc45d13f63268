#include "module_frames.h"

#include <algorithm>
#include <cmath>
#include <memory>
#include <string>

namespace caustics::test {

float luminance(const glm::vec3& v) { return 0.2126f * v.x + 0.7152f * v.y + 0.0722f * v.z; }

ViewRequest viewOf(const scene::Camera& camera, uint32_t size, ModuleOutput output, CausticsView* view) {
    ViewRequest v;
    v.inputs.camera = cameraViewMatrices(camera, size, size);
    v.inputs.width = v.inputs.height = size;
    v.inputs.view = view;
    v.output = output;
    return v;
}

Result<std::vector<std::vector<FrameImage>>> runModuleFrames(
    rhi::IDevice& device, CausticsModule& module, uint32_t frames, uint32_t framesInFlight,
    const std::function<std::vector<ViewRequest>(uint32_t frame)>& frameViews, FrameOrder order) {
    std::vector<std::unique_ptr<rg::RenderGraph>> graphs;
    std::vector<rhi::CommandListHandle> lists;
    std::vector<uint64_t> fences(framesInFlight, 0);
    for (uint32_t i = 0; i < framesInFlight; ++i) {
        graphs.push_back(std::make_unique<rg::RenderGraph>());
        CAUSTICS_TRY(rhi::CommandListHandle cmd, device.createCommandList());
        lists.push_back(cmd);
    }
    struct Pending {
        rhi::BufferHandle buffer;
        uint32_t width = 0, height = 0;
    };
    std::vector<std::vector<Pending>> pending(frames);
    // Builds frame n's graph: the slot's previous frame must be done before its graph, list and
    // per-frame buffers are reused.
    auto build = [&](uint32_t n) -> Status {
        const uint32_t slot = n % framesInFlight;
        if (fences[slot]) CAUSTICS_CHECK(device.waitForFence(fences[slot]));
        fences[slot] = 0;
        rg::RenderGraph& graph = *graphs[slot];
        graph.reset();
        for (ViewRequest& request : frameViews(n)) {
            request.inputs.frameIndex = n;
            CAUSTICS_TRY(FrameOutputs out, module.addPasses(graph, request.inputs));
            rg::RgTexture image = request.output == ModuleOutput::FirstType    ? out.firstType
                                  : request.output == ModuleOutput::SecondType ? out.secondType
                                                                               : out.caustics;
            if (!image.valid()) return makeError("runModuleFrames: the requested output is not produced");
            const uint32_t w = request.inputs.width, h = request.inputs.height;
            CAUSTICS_TRY(rhi::BufferHandle readback,
                         device.createBuffer(rhi::BufferDesc().setByteSize(uint64_t(w) * h * 16)
                                                 .setUsage(rhi::BufferUsage::CopyDest)
                                                 .setMemory(rhi::MemoryType::Readback)
                                                 .setDebugName("test readback")));
            graph.addPass("test.readback." + std::to_string(pending[n].size()), [&](rg::PassBuilder& b) {
                rg::RgTexture src = b.read(image, rg::Access::CopySource);
                b.setSideEffects();
                return [src, readback](rg::PassContext& ctx) { ctx.cmd().copyTextureToBuffer(readback, 0, ctx.texture(src)); };
            });
            pending[n].push_back({readback, w, h});
        }
        return okStatus();
    };
    auto execute = [&](uint32_t n) -> Status {
        const uint32_t slot = n % framesInFlight;
        rhi::ICommandList& cmd = *lists[slot];
        cmd.begin();
        CAUSTICS_CHECK(graphs[slot]->execute(device, cmd));
        cmd.end();
        CAUSTICS_TRY(fences[slot], device.submit(lists[slot]));
        return okStatus();
    };
    if (order == FrameOrder::BuildAhead && framesInFlight < 2)
        return makeError("runModuleFrames: building ahead needs two graphs (framesInFlight >= 2)");
    for (uint32_t n = 0; n < frames; ++n) {
        if (order == FrameOrder::InTurn) {
            CAUSTICS_CHECK(build(n));
            CAUSTICS_CHECK(execute(n));
            continue;
        }
        // A render thread one frame ahead of the GPU: frame n + 1 is built before frame n executes.
        if (n == 0) CAUSTICS_CHECK(build(0));
        if (n + 1 < frames) CAUSTICS_CHECK(build(n + 1));
        CAUSTICS_CHECK(execute(n));
    }
    CAUSTICS_CHECK(device.waitIdle());
    std::vector<std::vector<FrameImage>> images(frames);
    for (uint32_t n = 0; n < frames; ++n)
        for (const Pending& p : pending[n]) {
            std::vector<glm::vec4> rgba(size_t(p.width) * p.height);
            if (!device.readBuffer(p.buffer, rgba.data(), rgba.size() * sizeof(glm::vec4)))
                return makeError("runModuleFrames: readback failed");
            FrameImage img{p.width, p.height, {}};
            img.pixels.reserve(rgba.size());
            for (const glm::vec4& v : rgba) img.pixels.push_back(glm::vec3(v));
            images[n].push_back(std::move(img));
        }
    return images;
}

double relativeL1(const FrameImage& a, const FrameImage& b) {
    double diff = 0.0, sum = 0.0;
    for (size_t i = 0; i < b.pixels.size() && i < a.pixels.size(); ++i) {
        diff += std::abs(double(luminance(a.pixels[i])) - luminance(b.pixels[i]));
        sum += std::abs(double(luminance(b.pixels[i])));
    }
    return sum > 0.0 ? diff / sum : (diff > 0.0 ? 1e9 : 0.0);
}

double totalLuminance(const FrameImage& img) {
    double sum = 0.0;
    for (const glm::vec3& v : img.pixels) sum += luminance(v);
    return sum;
}

glm::vec2 peakCentroid(const std::vector<glm::vec3>& pixels, uint32_t width, uint32_t height, float fraction) {
    std::vector<float> blurred(size_t(width) * height, 0.0f);
    float maxValue = 0.0f;
    for (uint32_t y = 0; y < height; ++y)
        for (uint32_t x = 0; x < width; ++x) {
            float s = 0.0f;
            int n = 0;
            for (int dy = -1; dy <= 1; ++dy)
                for (int dx = -1; dx <= 1; ++dx) {
                    int xx = int(x) + dx, yy = int(y) + dy;
                    if (xx < 0 || yy < 0 || xx >= int(width) || yy >= int(height)) continue;
                    s += luminance(pixels[size_t(yy) * width + xx]);
                    ++n;
                }
            blurred[size_t(y) * width + x] = s / float(n);
            maxValue = std::max(maxValue, blurred[size_t(y) * width + x]);
        }
    glm::dvec2 c(0.0);
    double w = 0.0;
    for (uint32_t y = 0; y < height; ++y)
        for (uint32_t x = 0; x < width; ++x) {
            float v = blurred[size_t(y) * width + x];
            if (v < fraction * maxValue || v <= 0.0f) continue;
            c += glm::dvec2(x + 0.5, y + 0.5) * double(v);
            w += v;
        }
    return w > 0.0 ? glm::vec2(c / w) : glm::vec2(-1.0f);
}

}  // namespace caustics::test
