#include "module/pass_bindings.h"

#include <algorithm>

#include "caustics/pass_shaders.h"

namespace caustics {
namespace {

using shader_bindings::Kind;

static_assert(uint8_t(Kind::ConstantBuffer) == uint8_t(rhi::BindingType::ConstantBuffer) &&
              uint8_t(Kind::StorageBufferRO) == uint8_t(rhi::BindingType::StorageBufferRO) &&
              uint8_t(Kind::StorageBufferRW) == uint8_t(rhi::BindingType::StorageBufferRW) &&
              uint8_t(Kind::SampledTexture) == uint8_t(rhi::BindingType::SampledTexture) &&
              uint8_t(Kind::StorageTexture) == uint8_t(rhi::BindingType::StorageTexture) &&
              uint8_t(Kind::Sampler) == uint8_t(rhi::BindingType::Sampler) &&
              uint8_t(Kind::AccelStruct) == uint8_t(rhi::BindingType::AccelStruct));

rhi::BindingType typeOf(Kind k) { return rhi::BindingType(uint8_t(k)); }

std::string kindName(Kind k) {
    switch (k) {
        case Kind::ConstantBuffer: return "constant buffer";
        case Kind::StorageBufferRO: return "read-only storage buffer";
        case Kind::StorageBufferRW: return "storage buffer";
        case Kind::SampledTexture: return "sampled texture";
        case Kind::StorageTexture: return "storage texture";
        case Kind::Sampler: return "sampler";
        case Kind::AccelStruct: return "acceleration structure";
    }
    return "binding";
}

std::string declaredAs(std::string_view name, Kind k, const char* wanted) {
    return "'" + std::string(name) + "' is declared as a " + kindName(k) + ", not " + wanted;
}

}  // namespace

Result<rhi::BindingLayoutHandle> createPassBindingLayout(rhi::IDevice& device, const shader_bindings::PassBindings& pass,
                                                         uint32_t set, rhi::ShaderStage visibility) {
    rhi::BindingLayoutDesc desc;
    desc.setVisibility(visibility);
    for (const shader_bindings::Binding& b : pass.bindings)
        if (b.set == set) desc.add(b.slot, typeOf(b.kind), b.count);
    if (desc.items.empty())
        return makeError(std::string(pass.name) + ": no binding is declared in set " + std::to_string(set));
    return device.createBindingLayout(desc);
}

const shader_bindings::Binding* PassBindingSet::find(std::string_view name, const char* what) {
    for (const shader_bindings::Binding& b : pass_->bindings) {
        if (b.name != name || b.set != set_) continue;
        filled_.push_back(name);
        return &b;
    }
    errors_.push_back("'" + std::string(name) + "' (" + what + ") is not a binding of set " + std::to_string(set_));
    return nullptr;
}

PassBindingSet& PassBindingSet::texture(std::string_view name, rhi::TextureHandle texture) {
    const shader_bindings::Binding* b = find(name, "texture");
    if (!b) return *this;
    if (b->count != 1)
        errors_.push_back("'" + std::string(name) + "' is an array of " + std::to_string(b->count) + " (textures(), not texture())");
    else if (b->kind == Kind::SampledTexture) desc_.add(rhi::BindingSetItem::sampledTexture(b->slot, std::move(texture)));
    else if (b->kind == Kind::StorageTexture) desc_.add(rhi::BindingSetItem::storageTexture(b->slot, std::move(texture)));
    else errors_.push_back(declaredAs(name, b->kind, "a texture"));
    return *this;
}

PassBindingSet& PassBindingSet::textures(std::string_view name, std::span<const rhi::TextureHandle> textures) {
    const shader_bindings::Binding* b = find(name, "texture array");
    if (!b) return *this;
    if (b->kind != Kind::SampledTexture) errors_.push_back(declaredAs(name, b->kind, "a texture array"));
    else if (textures.size() != b->count)
        errors_.push_back("'" + std::string(name) + "' is an array of " + std::to_string(b->count) + ", given " +
                          std::to_string(textures.size()) + " textures");
    else
        for (uint32_t i = 0; i < b->count; ++i) desc_.add(rhi::BindingSetItem::sampledTexture(b->slot, textures[i], i));
    return *this;
}

PassBindingSet& PassBindingSet::buffer(std::string_view name, rhi::BufferHandle buffer) {
    const shader_bindings::Binding* b = find(name, "buffer");
    if (!b) return *this;
    if (b->kind == Kind::StorageBufferRO || b->kind == Kind::StorageBufferRW)
        desc_.add(rhi::BindingSetItem::storageBuffer(b->slot, std::move(buffer), b->kind == Kind::StorageBufferRW));
    else if (b->kind == Kind::ConstantBuffer) desc_.add(rhi::BindingSetItem::constantBuffer(b->slot, std::move(buffer)));
    else errors_.push_back(declaredAs(name, b->kind, "a buffer"));
    return *this;
}

PassBindingSet& PassBindingSet::sampler(std::string_view name, rhi::SamplerHandle sampler) {
    const shader_bindings::Binding* b = find(name, "sampler");
    if (!b) return *this;
    if (b->kind == Kind::Sampler) desc_.add(rhi::BindingSetItem::samplerItem(b->slot, std::move(sampler)));
    else errors_.push_back(declaredAs(name, b->kind, "a sampler"));
    return *this;
}

PassBindingSet& PassBindingSet::accelStruct(std::string_view name, rhi::AccelStructHandle accelStruct) {
    const shader_bindings::Binding* b = find(name, "acceleration structure");
    if (!b) return *this;
    if (b->kind == Kind::AccelStruct) desc_.add(rhi::BindingSetItem::accelStructItem(b->slot, std::move(accelStruct)));
    else errors_.push_back(declaredAs(name, b->kind, "an acceleration structure"));
    return *this;
}

Result<rhi::BindingSetDesc> PassBindingSet::desc() const {
    std::vector<std::string> errors = errors_;
    for (const shader_bindings::Binding& b : pass_->bindings)
        if (b.set == set_ && std::count(filled_.begin(), filled_.end(), b.name) != 1)
            errors.push_back("'" + std::string(b.name) + "' is " + (std::count(filled_.begin(), filled_.end(), b.name) ? "set twice" : "not set"));
    if (errors.empty()) return desc_;
    std::string message = std::string(pass_->name) + " bindings (set " + std::to_string(set_) + "):";
    for (const std::string& e : errors) message += " " + e + ";";
    return makeError(message);
}

Result<rhi::ComputePipelineHandle> createPassComputePipeline(rhi::IDevice& device, const char* shader,
                                                             std::vector<rhi::BindingLayoutHandle> layouts, uint32_t pushBytes) {
    rhi::ComputePipelineDesc desc;
    CAUSTICS_TRY(desc.shader.code, pass_shaders::shaderCode(device.backend(), shader));
    desc.shader.stage = rhi::ShaderStage::Compute;
    desc.bindings.layouts = std::move(layouts);
    desc.bindings.pushConstantBytes = pushBytes;
    desc.debugName = shader;
    return device.createComputePipeline(desc);
}

}  // namespace caustics
