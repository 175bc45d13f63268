#include "vk_state_object.h"

#include <cstring>

#include "vk_device.h"

namespace caustics::rhi::vulkan {
namespace {

std::string nameOf(const StateObjectDesc& desc) {
    return "state object" + (desc.debugName.empty() ? std::string() : " '" + desc.debugName + "'");
}

bool isGeneral(ShaderStage stage) {
    return stage == ShaderStage::RayGen || stage == ShaderStage::Miss || stage == ShaderStage::Callable;
}

const char* stageName(ShaderStage stage) {
    switch (stage) {
        case ShaderStage::RayGen: return "raygen";
        case ShaderStage::Miss: return "miss";
        case ShaderStage::Callable: return "callable";
        case ShaderStage::ClosestHit: return "closest-hit";
        case ShaderStage::AnyHit: return "any-hit";
        case ShaderStage::Intersection: return "intersection";
        default: return "non-ray-tracing";
    }
}

}  // namespace

Result<RayTracingGroupPlan> planRayTracingGroups(const StateObjectDesc& desc) {
    RayTracingGroupPlan plan;
    std::unordered_map<std::string, uint32_t> stageByName;
    for (uint32_t l = 0; l < desc.libraries.size(); ++l) {
        const auto& exports = desc.libraries[l].exports;
        for (uint32_t e = 0; e < exports.size(); ++e) {
            const ShaderExport& ex = exports[e];
            if (!hasAny(ex.stage, ShaderStage::AllRayTracing) || (uint32_t(ex.stage) & (uint32_t(ex.stage) - 1)) != 0)
                return makeError(nameOf(desc) + ": export '" + ex.name + "' must have exactly one ray-tracing stage");
            if (!stageByName.emplace(ex.name, uint32_t(plan.stages.size())).second)
                return makeError(nameOf(desc) + ": export name '" + ex.name + "' is used twice");
            plan.stages.push_back({l, e, ex.stage});
        }
    }
    auto general = [](uint32_t stageIndex) {
        VkRayTracingShaderGroupCreateInfoKHR g{VK_STRUCTURE_TYPE_RAY_TRACING_SHADER_GROUP_CREATE_INFO_KHR};
        g.type = VK_RAY_TRACING_SHADER_GROUP_TYPE_GENERAL_KHR;
        g.generalShader = stageIndex;
        g.closestHitShader = g.anyHitShader = g.intersectionShader = VK_SHADER_UNUSED_KHR;
        return g;
    };
    bool hasRayGen = false;
    for (uint32_t s = 0; s < plan.stages.size(); ++s) {
        if (!isGeneral(plan.stages[s].stage)) continue;
        hasRayGen |= plan.stages[s].stage == ShaderStage::RayGen;
        const ShaderExport& ex = desc.libraries[plan.stages[s].library].exports[plan.stages[s].exportIndex];
        plan.groupByName[ex.name] = uint32_t(plan.groups.size());
        plan.groups.push_back(general(s));
    }
    if (!hasRayGen) return makeError(nameOf(desc) + ": no raygen export");

    for (const HitGroupDesc& hg : desc.hitGroups) {
        // Resolves one member of a hit group: empty = unused; otherwise an export of the expected stage.
        auto member = [&](const std::string& exportName, ShaderStage expected, const char* role) -> Result<uint32_t> {
            if (exportName.empty()) return VK_SHADER_UNUSED_KHR;
            auto it = stageByName.find(exportName);
            if (it == stageByName.end())
                return makeError(nameOf(desc) + ": hit group '" + hg.name + "' names " + role + " export '" +
                                 exportName + "', which no library exports");
            if (plan.stages[it->second].stage != expected)
                return makeError(nameOf(desc) + ": hit group '" + hg.name + "' uses export '" + exportName + "' as " +
                                 role + " but it is a " + stageName(plan.stages[it->second].stage) + " shader");
            return it->second;
        };
        VkRayTracingShaderGroupCreateInfoKHR g{VK_STRUCTURE_TYPE_RAY_TRACING_SHADER_GROUP_CREATE_INFO_KHR};
        g.generalShader = VK_SHADER_UNUSED_KHR;
        CAUSTICS_TRY(g.closestHitShader, member(hg.closestHit, ShaderStage::ClosestHit, "closest-hit"));
        CAUSTICS_TRY(g.anyHitShader, member(hg.anyHit, ShaderStage::AnyHit, "any-hit"));
        CAUSTICS_TRY(g.intersectionShader, member(hg.intersection, ShaderStage::Intersection, "intersection"));
        if (hg.type == HitGroupType::Procedural) {
            if (g.intersectionShader == VK_SHADER_UNUSED_KHR)
                return makeError(nameOf(desc) + ": procedural hit group '" + hg.name + "' has no intersection export");
            g.type = VK_RAY_TRACING_SHADER_GROUP_TYPE_PROCEDURAL_HIT_GROUP_KHR;
        } else {
            if (g.intersectionShader != VK_SHADER_UNUSED_KHR)
                return makeError(nameOf(desc) + ": triangle hit group '" + hg.name +
                                 "' must not have an intersection export (make it Procedural)");
            g.type = VK_RAY_TRACING_SHADER_GROUP_TYPE_TRIANGLES_HIT_GROUP_KHR;
        }
        if (hg.name.empty() || !plan.groupByName.emplace(hg.name, uint32_t(plan.groups.size())).second)
            return makeError(nameOf(desc) + ": hit group name '" + hg.name + "' is empty or already used by an export or "
                             "another hit group");
        plan.groups.push_back(g);
    }
    return plan;
}

Result<std::shared_ptr<VulkanStateObject>> VulkanStateObject::create(const ContextPtr& context,
                                                                     const StateObjectDesc& desc) {
    if (!context->fn.vkCreateRayTracingPipelinesKHR)
        return makeError(nameOf(desc) + ": the device has no VK_KHR_ray_tracing_pipeline");
    const uint32_t maxDepth = context->rayTracingProperties.maxRayRecursionDepth;
    if (desc.maxRecursionDepth > maxDepth)
        return makeError(nameOf(desc) + ": maxRecursionDepth " + std::to_string(desc.maxRecursionDepth) +
                         " exceeds the device's maxRayRecursionDepth " + std::to_string(maxDepth) +
                         " (trace iteratively from the raygen shader instead of recursing)");
    CAUSTICS_TRY(RayTracingGroupPlan plan, planRayTracingGroups(desc));

    std::shared_ptr<VulkanStateObject> so(new VulkanStateObject(desc));
    so->context_ = context;
    so->bindPoint_ = VK_PIPELINE_BIND_POINT_RAY_TRACING_KHR;
    so->handleSize_ = context->rayTracingProperties.shaderGroupHandleSize;
    so->groupByName_ = plan.groupByName;

    // One module per library; every export of it is an entry point (pName) of that module.
    std::vector<VkShaderModule> modules;
    auto destroyModules = [&] {
        for (VkShaderModule m : modules) context->fn.vkDestroyShaderModule(context->device, m, nullptr);
    };
    for (const ShaderLibraryDesc& lib : desc.libraries) {
        auto module = createShaderModule(*context, lib.code);
        if (!module) {
            destroyModules();
            return makeError(nameOf(desc) + ": " + module.message());
        }
        modules.push_back(module.value());
    }
    std::vector<VkPipelineShaderStageCreateInfo> stages;
    for (const RayTracingGroupPlan::Stage& s : plan.stages) {
        VkPipelineShaderStageCreateInfo info{VK_STRUCTURE_TYPE_PIPELINE_SHADER_STAGE_CREATE_INFO};
        info.stage = toVkShaderStage(s.stage);
        info.module = modules[s.library];
        info.pName = desc.libraries[s.library].exports[s.exportIndex].entryPoint.c_str();
        stages.push_back(info);
    }

    auto layout = createPipelineLayout(*context, desc.globalBindings, desc.debugName);
    if (!layout) {
        destroyModules();
        return layout.error();
    }
    so->layout_ = layout.value();

    // maxPayloadBytes / maxAttributeBytes only matter for pipeline libraries
    // (VkRayTracingPipelineInterfaceCreateInfoKHR); a complete pipeline derives them from its shaders.
    VkRayTracingPipelineCreateInfoKHR info{VK_STRUCTURE_TYPE_RAY_TRACING_PIPELINE_CREATE_INFO_KHR};
    info.stageCount = uint32_t(stages.size());
    info.pStages = stages.data();
    info.groupCount = uint32_t(plan.groups.size());
    info.pGroups = plan.groups.data();
    info.maxPipelineRayRecursionDepth = desc.maxRecursionDepth;
    info.layout = so->layout_;
    VkResult r = context->fn.vkCreateRayTracingPipelinesKHR(context->device, VK_NULL_HANDLE, VK_NULL_HANDLE, 1, &info,
                                                            nullptr, &so->pipeline_);
    destroyModules();
    if (r != VK_SUCCESS) return vkError(r, "vkCreateRayTracingPipelinesKHR", desc.debugName);
    if (!desc.debugName.empty()) context->setName(VK_OBJECT_TYPE_PIPELINE, so->pipeline_, desc.debugName);

    so->handles_.resize(size_t(plan.groups.size()) * so->handleSize_);
    r = context->fn.vkGetRayTracingShaderGroupHandlesKHR(context->device, so->pipeline_, 0, info.groupCount,
                                                         so->handles_.size(), so->handles_.data());
    if (r != VK_SUCCESS) return vkError(r, "vkGetRayTracingShaderGroupHandlesKHR", desc.debugName);
    return so;
}

const uint8_t* VulkanStateObject::groupHandle(const std::string& name) const {
    auto it = groupByName_.find(name);
    return it == groupByName_.end() ? nullptr : handles_.data() + size_t(it->second) * handleSize_;
}

std::vector<uint8_t> VulkanStateObject::shaderIdentifier(const std::string& exportName) const {
    const uint8_t* handle = groupHandle(exportName);
    return handle ? std::vector<uint8_t>(handle, handle + handleSize_) : std::vector<uint8_t>{};
}

Result<StateObjectHandle> VulkanDevice::createStateObject(const StateObjectDesc& desc) {
    auto so = VulkanStateObject::create(contextPtr(), desc);
    if (!so) return so.error();
    return StateObjectHandle(so.value());
}

}  // namespace caustics::rhi::vulkan
