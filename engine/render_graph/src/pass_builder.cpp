#include "caustics/render_graph/pass_builder.h"

#include "caustics/render_graph/render_graph.h"

namespace caustics::rg {

RgTexture PassBuilder::createTexture(std::string name, const rhi::TextureDesc& desc) {
    ResourceDecl decl;
    decl.kind = ResourceKind::Texture;
    decl.name = std::move(name);
    decl.textureDesc = desc;
    return {graph_.addResource(std::move(decl)), 0};
}

RgBuffer PassBuilder::createBuffer(std::string name, const rhi::BufferDesc& desc) {
    ResourceDecl decl;
    decl.kind = ResourceKind::Buffer;
    decl.name = std::move(name);
    decl.bufferDesc = desc;
    return {graph_.addResource(std::move(decl)), 0};
}

uint32_t PassBuilder::access(ResourceKind kind, uint32_t index, uint32_t version, Access access, bool write) {
    GraphDesc& g = graph_.desc_;
    PassDecl& pass = g.passes[pass_];
    if (index >= g.resources.size() || g.resources[index].kind != kind) {
        graph_.setupError("render graph: pass '" + pass.name + "' uses an invalid " + resourceKindName(kind) +
                          " handle");
        return version;
    }
    ResourceDecl& res = g.resources[index];
    if (!write) {
        pass.accesses.push_back({index, version, access, false});
        return version;
    }
    bool alreadyWritten = false;
    for (const AccessDecl& a : pass.accesses) alreadyWritten |= a.write && a.resource == index;
    // Several writes of one resource in one pass produce one new version.
    if (!alreadyWritten) {
        if (version != res.latestVersion) {
            graph_.setupError("render graph: pass '" + pass.name + "' writes " + resourceKindName(kind) + " '" +
                              res.name + "' through stale version " + std::to_string(version) + " (version " +
                              std::to_string(res.latestVersion) + " is current)");
        }
        ++res.latestVersion;
    }
    pass.accesses.push_back({index, res.latestVersion, access, true});
    return res.latestVersion;
}

void PassBuilder::setStages(rhi::PipelineStages stages) { graph_.desc_.passes[pass_].stages = stages; }

RgTexture PassBuilder::read(RgTexture t, Access a) { return {t.index, access(ResourceKind::Texture, t.index, t.version, a, false)}; }
RgBuffer PassBuilder::read(RgBuffer b, Access a) { return {b.index, access(ResourceKind::Buffer, b.index, b.version, a, false)}; }
RgAccelStruct PassBuilder::read(RgAccelStruct s, Access a) {
    return {s.index, access(ResourceKind::AccelStruct, s.index, s.version, a, false)};
}
RgTexture PassBuilder::write(RgTexture t, Access a) { return {t.index, access(ResourceKind::Texture, t.index, t.version, a, true)}; }
RgBuffer PassBuilder::write(RgBuffer b, Access a) { return {b.index, access(ResourceKind::Buffer, b.index, b.version, a, true)}; }
RgAccelStruct PassBuilder::write(RgAccelStruct s, Access a) {
    return {s.index, access(ResourceKind::AccelStruct, s.index, s.version, a, true)};
}

}  // namespace caustics::rg
