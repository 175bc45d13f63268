#include "frame_budget.h"

#include <cstdio>
#include <string>

#include "caustics/caustic_passes.h"

namespace caustics::sample {
namespace {

// Per pixel, what a frame keeps alive at once (formats from caustics/gbuffer.h and the passes):
constexpr uint64_t kGBufferBytes = 4 + 8 + 4 + 8 + 4 + 4;   // depth, normal, albedo, optics, linear depth, id
constexpr uint64_t kDirectBytes = 8;                         // RGBA16F
constexpr uint64_t kCompositeBytes = 4 + 16;                 // display RGBA8 + hdr RGBA32F
constexpr uint64_t kReadbackBytes = 4 + 16;                  // the sample's host copies of both
constexpr uint64_t kCausticBytes = 12 + 12 + 16 + 16 + 16;   // radiance buffers (RGB) + three RGBA32F textures
constexpr uint64_t kHdrReadbackBytes = 16;                   // the largest single allocation the sample makes

std::string gib(uint64_t bytes) {
    char text[32];
    std::snprintf(text, sizeof(text), "%.1f GiB", double(bytes) / double(1ull << 30));
    return text;
}

}  // namespace

uint64_t estimateFrameBytes(uint32_t width, uint32_t height, const CausticsSettings& settings) {
    uint64_t perPixel = kGBufferBytes + kDirectBytes + kCompositeBytes + kReadbackBytes;
    if (settings.causticsEnabled) perPixel += kCausticBytes;
    if (settings.causticsEnabled && settings.secondType) perPixel += sizeof(CausticSphere);
    return perPixel * width * height;
}

Status checkFrameFitsDevice(const rhi::Capabilities& caps, uint32_t width, uint32_t height,
                            const CausticsSettings& settings) {
    std::string size = std::to_string(width) + "x" + std::to_string(height);
    if (caps.maxTextureDimension2D && (width > caps.maxTextureDimension2D || height > caps.maxTextureDimension2D))
        return makeError("--width/--height: " + size + " exceeds the device's largest texture side " +
                         std::to_string(caps.maxTextureDimension2D) + " (" + caps.adapterName + ")");
    uint64_t readback = kHdrReadbackBytes * width * height;
    if (caps.maxAllocationBytes && readback > caps.maxAllocationBytes)
        return makeError("--width/--height: " + size + " needs a " + gib(readback) +
                         " read-back buffer, more than the device's largest allocation " +
                         gib(caps.maxAllocationBytes) + " (" + caps.adapterName + ")");
    uint64_t frame = estimateFrameBytes(width, height, settings);
    if (caps.deviceMemoryBytes && frame > caps.deviceMemoryBytes)
        return makeError("--width/--height: " + size + " needs at least " + gib(frame) + " of device memory, more than the " +
                         gib(caps.deviceMemoryBytes) + " the device has (" + caps.adapterName + ")");
    return okStatus();
}

}  // namespace caustics::sample
