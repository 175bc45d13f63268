#pragma once
// A pass's binding layout and binding sets from its one declaration (shaders/bindings/shader_binding.h;
// docs/shaders.md, "Bindings"): the layout lists the declared bindings of a set, and a set is filled by
// binding name, so a slot number is written only in the declaration.
#include <span>
#include <string>
#include <string_view>
#include <vector>

#include "bindings/shader_binding.h"
#include "caustics/rhi/device.h"

namespace caustics {

// The layout of descriptor set / register space `set`: every binding `pass` declares there.
Result<rhi::BindingLayoutHandle> createPassBindingLayout(rhi::IDevice& device, const shader_bindings::PassBindings& pass,
                                                         uint32_t set, rhi::ShaderStage visibility);

// The compute pipeline of a pass's shader entry (its pass_shaders name, "<pass>/<x>.comp") over the
// layouts of sets 0, 1, ... and `pushBytes` of push constants.
Result<rhi::ComputePipelineHandle> createPassComputePipeline(rhi::IDevice& device, const char* shader,
                                                             std::vector<rhi::BindingLayoutHandle> layouts, uint32_t pushBytes);

// The items of one binding set, by name. A name the pass does not declare in this set, a resource of
// the wrong kind, or a declared binding left out makes desc() an error naming the pass and the binding.
class PassBindingSet {
public:
    PassBindingSet(const shader_bindings::PassBindings& pass, uint32_t set) : pass_(&pass), set_(set) {}
    PassBindingSet& texture(std::string_view name, rhi::TextureHandle texture);   // sampled or storage
    // Every element of a texture array: `textures` holds exactly its declared count.
    PassBindingSet& textures(std::string_view name, std::span<const rhi::TextureHandle> textures);
    PassBindingSet& buffer(std::string_view name, rhi::BufferHandle buffer);      // storage or constant
    PassBindingSet& sampler(std::string_view name, rhi::SamplerHandle sampler);
    PassBindingSet& accelStruct(std::string_view name, rhi::AccelStructHandle accelStruct);
    Result<rhi::BindingSetDesc> desc() const;

private:
    const shader_bindings::Binding* find(std::string_view name, const char* what);
    const shader_bindings::PassBindings* pass_;
    uint32_t set_;
    rhi::BindingSetDesc desc_;
    std::vector<std::string_view> filled_;
    std::vector<std::string> errors_;
};

}  // namespace caustics
