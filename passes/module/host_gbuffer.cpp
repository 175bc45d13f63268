#include "host_gbuffer.h"

#include <string>

namespace caustics {

HostGBufferRequirements hostGBufferRequirements(const CausticsSettings& settings) {
    HostGBufferRequirements r;
    const bool ourLighting = !settings.causticsOnly;
    r.normalRoughness = settings.filter || ourLighting;
    r.albedoMetallic = ourLighting;
    r.optics = settings.secondType || ourLighting;
    return r;
}

namespace {

// The map must hold objectIdMapCount pairs and be bindable as a storage buffer.
Status checkObjectIdMap(const HostGBuffer& h) {
    const std::string what = "CausticsModule::addPasses: hostGBuffer.objectIdMap";
    if (!h.objectIdMap) {
        if (h.objectIdMapCount == 0) return okStatus();
        return makeError(what + " is missing but objectIdMapCount is " + std::to_string(h.objectIdMapCount));
    }
    const rhi::BufferDesc& d = h.objectIdMap->desc();
    const std::string label = d.debugName.empty() ? std::string() : " ('" + d.debugName + "')";
    if (h.objectIdMapCount == 0) return makeError(what + label + " is given with objectIdMapCount 0");
    if (d.byteSize < uint64_t(h.objectIdMapCount) * 8)
        return makeError(what + label + " holds " + std::to_string(d.byteSize / 8) + " (hostId, moduleId) pairs (" +
                         std::to_string(d.byteSize) + " bytes); objectIdMapCount is " +
                         std::to_string(h.objectIdMapCount));
    if (!rhi::hasAny(d.usage, rhi::BufferUsage::Storage))
        return makeError(what + label + " lacks Storage usage: the id pass reads it as a storage buffer");
    return okStatus();
}

}  // namespace

Result<GBuffer> importHostGBuffer(rg::RenderGraph& graph, const HostGBuffer& h, uint32_t width, uint32_t height,
                                  const CausticsSettings& settings, const ObjectIdRemapPass& remap) {
    CAUSTICS_CHECK(checkObjectIdMap(h));
    const HostGBufferRequirements need = hostGBufferRequirements(settings);
    GBuffer g;
    g.width = width;
    g.height = height;
    auto import = [&](const rhi::TextureHandle& t, const char* name, rhi::Format format, bool required,
                      rg::RgTexture& out) -> Status {
        const std::string what = std::string("CausticsModule::addPasses: hostGBuffer.") + name;
        if (!t) {
            if (required) return makeError(what + " is missing; this configuration reads it (docs/embedding.md, \"G-buffer\")");
            return okStatus();
        }
        const rhi::TextureDesc& d = t->desc();
        const std::string label = d.debugName.empty() ? std::string() : " ('" + d.debugName + "')";
        if (d.format != format)
            return makeError(what + label + " has format " + rhi::formatInfo(d.format).name + ", expected " +
                             rhi::formatInfo(format).name);
        if (d.width != width || d.height != height)
            return makeError(what + label + " is " + std::to_string(d.width) + "x" + std::to_string(d.height) +
                             ", expected the image size " + std::to_string(width) + "x" + std::to_string(height));
        if (!rhi::hasAny(d.usage, rhi::TextureUsage::Sampled))
            return makeError(what + label + " lacks Sampled usage: the passes read it as a sampled texture");
        out = graph.importTexture(std::string("host.") + name, t, h.state, h.state);
        return okStatus();
    };
    CAUSTICS_CHECK(import(h.linearDepth, "linearDepth", GBufferFormats::kLinearDepth, true, g.linearDepth));
    CAUSTICS_CHECK(import(h.objectId, "objectId", GBufferFormats::kObjectId, true, g.objectId));
    CAUSTICS_CHECK(import(h.optics, "optics", GBufferFormats::kOptics, need.optics, g.optics));
    CAUSTICS_CHECK(import(h.normalRoughness, "normalRoughness", GBufferFormats::kNormalRoughness, need.normalRoughness,
                          g.normalRoughness));
    CAUSTICS_CHECK(import(h.albedoMetallic, "albedoMetallic", GBufferFormats::kAlbedoMetallic, need.albedoMetallic,
                          g.albedoMetallic));
    // depth is not imported: nothing reads it, and an unread import would only add barriers.
    if (h.objectIdMap) {
        rg::RgBuffer map = graph.importBuffer("host.objectIdMap", h.objectIdMap, rhi::ResourceState::ShaderResource,
                                              rhi::ResourceState::ShaderResource);
        g.objectId = remap.addToGraph(graph, g.objectId, map, h.objectIdMapCount, width, height);
    }
    return g;
}

}  // namespace caustics
