#include "caustics/render_graph/render_graph.h"

#include "execution_state.h"

namespace caustics::rg {

RenderGraph::RenderGraph() : exec_(std::make_unique<ExecutionState>()) {}
RenderGraph::~RenderGraph() = default;

uint32_t RenderGraph::addPass(std::string name, const PassSetupFn& setup) {
    uint32_t index = uint32_t(desc_.passes.size());
    desc_.passes.push_back({std::move(name), false, {}});
    PassBuilder builder(*this, index);
    PassExecuteFn execute = setup ? setup(builder) : PassExecuteFn{};
    desc_.passes[index].sideEffects = builder.sideEffects_;
    executes_.push_back(std::move(execute));
    plan_.reset();
    return index;
}

uint32_t RenderGraph::addResource(ResourceDecl decl) {
    desc_.resources.push_back(std::move(decl));
    imported_.textures.emplace_back();
    imported_.buffers.emplace_back();
    imported_.accelStructs.emplace_back();
    plan_.reset();
    return uint32_t(desc_.resources.size() - 1);
}

void RenderGraph::setupError(std::string message) {
    if (setupError_.empty()) setupError_ = std::move(message);
}

namespace {
ResourceDecl importDecl(ResourceKind kind, std::string name, rhi::ResourceState current, rhi::ResourceState final) {
    ResourceDecl decl;
    decl.kind = kind;
    decl.name = std::move(name);
    decl.imported = true;
    decl.initialState = current;
    decl.finalState = final;
    return decl;
}

// An object imported earlier in this graph (several views in one graph share the module's persistent
// objects): the same resource at its latest version, so the graph orders and barriers every use of it;
// the new final state wins. kInvalidIndex when the object is new to this graph.
template <typename Handle>
uint32_t findImport(const std::vector<Handle>& imported, const Handle& object) {
    if (!object) return kInvalidIndex;
    for (uint32_t i = 0; i < imported.size(); ++i)
        if (imported[i] == object) return i;
    return kInvalidIndex;
}
}  // namespace

RgTexture RenderGraph::importTexture(std::string name, rhi::TextureHandle texture, rhi::ResourceState current,
                                     rhi::ResourceState final) {
    if (!texture) setupError("render graph: importTexture('" + name + "') got a null texture");
    if (uint32_t seen = findImport(imported_.textures, texture); seen != kInvalidIndex) {
        desc_.resources[seen].finalState = final;
        return {seen, desc_.resources[seen].latestVersion};
    }
    uint32_t index = addResource(importDecl(ResourceKind::Texture, std::move(name), current, final));
    if (texture) desc_.resources[index].textureDesc = texture->desc();
    imported_.textures[index] = std::move(texture);
    return {index, 0};
}

RgBuffer RenderGraph::importBuffer(std::string name, rhi::BufferHandle buffer, rhi::ResourceState current,
                                   rhi::ResourceState final) {
    if (!buffer) setupError("render graph: importBuffer('" + name + "') got a null buffer");
    if (uint32_t seen = findImport(imported_.buffers, buffer); seen != kInvalidIndex) {
        desc_.resources[seen].finalState = final;
        return {seen, desc_.resources[seen].latestVersion};
    }
    uint32_t index = addResource(importDecl(ResourceKind::Buffer, std::move(name), current, final));
    if (buffer) desc_.resources[index].bufferDesc = buffer->desc();
    imported_.buffers[index] = std::move(buffer);
    return {index, 0};
}

RgAccelStruct RenderGraph::importAccelStruct(std::string name, rhi::AccelStructHandle as, rhi::ResourceState current,
                                             rhi::ResourceState final) {
    if (!as) setupError("render graph: importAccelStruct('" + name + "') got a null acceleration structure");
    if (uint32_t seen = findImport(imported_.accelStructs, as); seen != kInvalidIndex) {
        desc_.resources[seen].finalState = final;
        return {seen, desc_.resources[seen].latestVersion};
    }
    uint32_t index = addResource(importDecl(ResourceKind::AccelStruct, std::move(name), current, final));
    imported_.accelStructs[index] = std::move(as);
    return {index, 0};
}

void RenderGraph::markOutput(RgTexture texture, rhi::ResourceState final) {
    if (texture.index >= desc_.resources.size()) return setupError("render graph: markOutput got an invalid texture");
    ResourceDecl& res = desc_.resources[texture.index];
    res.output = true;
    if (!res.imported) res.finalState = final;
    plan_.reset();
}

void RenderGraph::markOutput(RgBuffer buffer, rhi::ResourceState final) {
    if (buffer.index >= desc_.resources.size()) return setupError("render graph: markOutput got an invalid buffer");
    ResourceDecl& res = desc_.resources[buffer.index];
    res.output = true;
    if (!res.imported) res.finalState = final;
    plan_.reset();
}

void RenderGraph::markOutput(RgAccelStruct as) {
    if (as.index >= desc_.resources.size()) return setupError("render graph: markOutput got an invalid handle");
    desc_.resources[as.index].output = true;
    plan_.reset();
}

void RenderGraph::expectConsumer(std::initializer_list<RgTexture> anyOf, std::string owner) {
    ExpectedConsumer expected{std::move(owner), {}};
    for (RgTexture t : anyOf)
        if (t.valid()) {
            if (t.index >= desc_.resources.size()) return setupError("render graph: expectConsumer got an invalid texture");
            expected.anyOf.push_back(t.index);
        }
    if (!expected.anyOf.empty()) desc_.expectedConsumers.push_back(std::move(expected));
    plan_.reset();
}

Status RenderGraph::compile(const IMemorySizer& sizer) {
    if (!setupError_.empty()) return makeError(setupError_);
    auto plan = compileGraph(desc_, sizer);
    if (!plan) return plan.error();
    plan_ = std::move(plan).value();
    return okStatus();
}

void RenderGraph::reset() {
    desc_ = {};
    executes_.clear();
    imported_ = {};
    plan_.reset();
    setupError_.clear();
}

rhi::TextureHandle RenderGraph::texture(RgTexture handle) const {
    const auto& list = exec_->physical.textures;
    return handle.index < list.size() ? list[handle.index] : nullptr;
}

rhi::BufferHandle RenderGraph::buffer(RgBuffer handle) const {
    const auto& list = exec_->physical.buffers;
    return handle.index < list.size() ? list[handle.index] : nullptr;
}

}  // namespace caustics::rg
