#include "caustics/gbuffer.h"

namespace caustics {

rhi::TextureDesc gbufferTextureDesc(rhi::Format format, uint32_t width, uint32_t height, const char* name) {
    // Usage flags are added by the graph from the declared accesses; CopySource lets tests and hosts
    // read a target back.
    return rhi::TextureDesc()
        .setSize(width, height)
        .setFormat(format)
        .setUsage(rhi::TextureUsage::Sampled | rhi::TextureUsage::CopySource)
        .setDebugName(name);
}

}  // namespace caustics
