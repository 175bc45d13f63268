#include "frame_budget.h"

#include "caustics/sphere_capacity.h"

#include <cstdio>
#include <string>
#include <utility>
#include <vector>

#include "caustics/caustic_passes.h"
#include "caustics/render_graph/memory_sizer.h"
#include "camera_setup.h"

namespace caustics::sample {
namespace {

constexpr uint64_t kHdrReadbackBytesPerPixel = 16;   // RGBA32F: the largest single allocation the sample makes
// The second-type sphere TLAS holds one instance per pixel; the RHI cannot size an acceleration
// structure without creating it, so only its instance descriptors (64 bytes each) are counted.
constexpr uint64_t kSphereInstanceBytes = 64;

// A size for a message: GiB from 1 GiB up, MiB below (a 4 MiB hit buffer is not "0.0 GiB").
std::string sizeText(uint64_t bytes) {
    char text[32];
    if (bytes >= (1ull << 30)) std::snprintf(text, sizeof(text), "%.1f GiB", double(bytes) / double(1ull << 30));
    else std::snprintf(text, sizeof(text), "%.1f MiB", double(bytes) / double(1ull << 20));
    return text;
}

struct GraphMemory {
    uint64_t heap = 0;
    std::vector<std::pair<std::string, uint64_t>> transients;   // heap-placed resources, name and bytes
};

// The module's frame graph at width x height, built and compiled against the device's memory
// requirements; never executed.
Status compileFrameGraph(rg::RenderGraph& graph, rhi::IDevice& device, CausticsModule& module, uint32_t width,
                         uint32_t height, uint32_t frameIndex = 0) {
    FrameInputs in;
    in.frameIndex = frameIndex;
    in.camera = cameraViewMatrices(scene::Camera{}, width, height);
    in.width = width;
    in.height = height;
    CAUSTICS_TRY(FrameOutputs out, module.addPasses(graph, in));
    graph.markOutput(out.display, rhi::ResourceState::CopySource);
    graph.markOutput(out.hdr, rhi::ResourceState::CopySource);
    return graph.compile(rg::DeviceMemorySizer(device));
}

// Its memory: the aliased heap and the heap-placed transients.
Result<GraphMemory> frameGraphMemory(rhi::IDevice& device, CausticsModule& module, uint32_t width, uint32_t height,
                                     uint32_t frameIndex = 0) {
    rg::RenderGraph graph;
    CAUSTICS_CHECK(compileFrameGraph(graph, device, module, width, height, frameIndex));
    const rg::CompiledPlan& plan = *graph.plan();
    GraphMemory m;
    m.heap = plan.heapSize;
    for (size_t i = 0; i < graph.desc().resources.size(); ++i) {
        if (!plan.heapOffset[i]) continue;
        const rg::ResourceDecl& r = graph.desc().resources[i];
        bool buffer = r.kind == rg::ResourceKind::Buffer;
        uint64_t bytes = buffer ? device.memoryRequirements(plan.bufferDescs[i]).size
                                : device.memoryRequirements(plan.textureDescs[i]).size;
        // The device sizes a resource by creating it unbound; one it refuses comes back as 0 bytes.
        if (bytes == 0)
            return makeError("frame memory: with these settings the device cannot create the render graph's " +
                             std::string(buffer ? "buffer '" : "texture '") + r.name + "'" +
                             (buffer ? " of " + sizeText(plan.bufferDescs[i].byteSize) : std::string()) + " (" +
                             device.capabilities().adapterName + ")");
        m.transients.emplace_back(r.name, bytes);
    }
    return m;
}

}  // namespace

Status checkFrameSize(const rhi::Capabilities& caps, uint32_t width, uint32_t height) {
    std::string size = std::to_string(width) + "x" + std::to_string(height);
    if (caps.maxTextureDimension2D && (width > caps.maxTextureDimension2D || height > caps.maxTextureDimension2D))
        return makeError("--width/--height: " + size + " exceeds the device's largest texture side " +
                         std::to_string(caps.maxTextureDimension2D) + " (" + caps.adapterName + ")");
    uint64_t readback = kHdrReadbackBytesPerPixel * width * height;
    if (caps.maxAllocationBytes && readback > caps.maxAllocationBytes)
        return makeError("--width/--height: " + size + " needs a " + sizeText(readback) +
                         " read-back buffer, more than the device's largest allocation " +
                         sizeText(caps.maxAllocationBytes) + " (" + caps.adapterName + ")");
    return okStatus();
}

uint64_t persistentFrameBytes(rhi::IDevice& device, uint32_t width, uint32_t height, const CausticsSettings& s) {
    auto texture = [&](rhi::Format f) { return device.memoryRequirements(rhi::TextureDesc().setSize(width, height).setFormat(f)).size; };
    auto readback = [&](uint64_t bytesPerPixel) {
        return device.memoryRequirements(rhi::BufferDesc().setByteSize(bytesPerPixel * width * height)
                                             .setUsage(rhi::BufferUsage::CopyDest).setMemory(rhi::MemoryType::Readback)).size;
    };
    uint64_t bytes = readback(4) + readback(kHdrReadbackBytesPerPixel);   // the sample's display and HDR copies
    if (s.causticsEnabled && s.filter)   // the view's filter history (caustic_resources.cpp ensureHistory)
        bytes += 2 * texture(rhi::Format::RGBA32_FLOAT) + texture(rhi::Format::R32_FLOAT) +
                 texture(rhi::Format::RGBA16_FLOAT) + texture(rhi::Format::R32_UINT);
    // The sphere TLAS's largest allocation at this size (caustics/sphere_capacity.h: it follows the
    // specular surfaces in view, which may cover every pixel).
    if (s.causticsEnabled && s.secondType) bytes += kSphereInstanceBytes * initialSphereAllocation(width * height, 1.0);
    return bytes;
}

Result<uint64_t> frameHeapBytes(rhi::IDevice& device, CausticsModule& module, uint32_t width, uint32_t height,
                                uint32_t nextFrameIndex) {
    CAUSTICS_TRY(GraphMemory graph, frameGraphMemory(device, module, width, height, nextFrameIndex));
    return graph.heap;
}

Result<FrameMemory> measureFrameMemory(rhi::IDevice& device, CausticsModule& module) {
    // Both under kMinSphereAllocation pixels (caustics/sphere_capacity.h), where the second type's sphere
    // list and instances take a slot per pixel like the images.
    constexpr uint32_t kSmall[2][2] = {{64, 48}, {128, 96}};
    GraphMemory graph[2];
    for (int i = 0; i < 2; ++i) {
        CAUSTICS_TRY(graph[i], frameGraphMemory(device, module, kSmall[i][0], kSmall[i][1]));
    }
    double pixels0 = double(kSmall[0][0]) * kSmall[0][1], pixels1 = double(kSmall[1][0]) * kSmall[1][1];
    FrameMemory m;
    m.heapBytesPerPixel = std::max(0.0, (double(graph[1].heap) - double(graph[0].heap)) / (pixels1 - pixels0));
    m.fixedBytes = uint64_t(std::max(0.0, double(graph[0].heap) - m.heapBytesPerPixel * pixels0));
    for (const auto& [name, bytes] : graph[1].transients)
        for (const auto& [smallName, smallBytes] : graph[0].transients)
            if (name == smallName && bytes == smallBytes && bytes > m.largestFixedBytes) {
                m.largestFixed = name;
                m.largestFixedBytes = bytes;
            }
    return m;
}

Result<std::vector<MemoryEntry>> moduleFrameReport(rhi::IDevice& device, CausticsModule& module, uint32_t width,
                                                   uint32_t height) {
    rg::RenderGraph graph;
    CAUSTICS_CHECK(compileFrameGraph(graph, device, module, width, height));
    std::vector<MemoryEntry> report = module.memoryReport();
    appendFrameMemory(graph, report);
    return report;
}

Status checkFrameFitsDevice(rhi::IDevice& device, CausticsModule& module, uint32_t width, uint32_t height,
                            uint32_t nextFrameIndex, const rhi::Capabilities* limitsOrNull) {
    const rhi::Capabilities& limits = limitsOrNull ? *limitsOrNull : device.capabilities();
    CAUSTICS_CHECK(checkFrameSize(limits, width, height));
    CAUSTICS_TRY(uint64_t heap, frameHeapBytes(device, module, width, height, nextFrameIndex));
    std::string size = std::to_string(width) + "x" + std::to_string(height);
    if (limits.maxAllocationBytes && heap > limits.maxAllocationBytes) {
        CAUSTICS_TRY(FrameMemory fit, measureFrameMemory(device, module));
        return makeError("frame memory: " + size + " with these settings needs a " + sizeText(heap) + " render-graph transient heap (one allocation; " +
                         "largest fixed part: " + fit.largestFixed + " " + sizeText(fit.largestFixedBytes) +
                         "), more than the device's largest allocation " + sizeText(limits.maxAllocationBytes) + " (" +
                         limits.adapterName + ")");
    }
    uint64_t frame = heap + persistentFrameBytes(device, width, height, module.settings());
    if (limits.deviceMemoryBytes && frame > limits.deviceMemoryBytes)
        return makeError("--width/--height: " + size + " needs " +
                         sizeText(frame) + " of device memory (measured from the frame's render graph), more than the " +
                         sizeText(limits.deviceMemoryBytes) + " the device has (" + limits.adapterName + ")");
    return okStatus();
}

}  // namespace caustics::sample
