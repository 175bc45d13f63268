#include "vk_shader_table.h"

#include <algorithm>
#include <cstring>

#include "vk_buffer.h"
#include "vk_command_list.h"
#include "vk_device.h"
#include "vk_state_object.h"

namespace caustics::rhi::vulkan {
namespace {

std::string nameOf(const ShaderTableDesc& desc) {
    return "shader table" + (desc.debugName.empty() ? std::string() : " '" + desc.debugName + "'");
}

uint32_t maxDataBytes(const std::vector<ShaderRecord>& records) {
    uint32_t bytes = 0;
    for (const ShaderRecord& r : records) bytes = std::max(bytes, uint32_t(r.localData.size()));
    return bytes;
}

}  // namespace

Result<ShaderTableImage> buildShaderTableImage(const ShaderTableDesc& desc, const ShaderTableAlignment& alignment,
                                               uint32_t localDataBytes,
                                               const std::function<const uint8_t*(const std::string&)>& handleOf) {
    ShaderTableCounts counts;
    counts.missCount = uint32_t(desc.missRecords.size());
    counts.hitGroupCount = uint32_t(desc.hitGroupRecords.size());
    counts.callableCount = uint32_t(desc.callableRecords.size());
    counts.rayGenDataBytes = uint32_t(desc.rayGen.localData.size());
    counts.missDataBytes = maxDataBytes(desc.missRecords);
    counts.hitGroupDataBytes = maxDataBytes(desc.hitGroupRecords);
    counts.callableDataBytes = maxDataBytes(desc.callableRecords);
    ShaderTableImage image;
    if (!computeShaderTableLayout(alignment, counts, image.layout))
        return makeError(nameOf(desc) + ": a record stride exceeds the device's maxShaderGroupStride " +
                         std::to_string(alignment.maxStride));
    image.bytes.assign(image.layout.totalBytes, 0);
    auto write = [&](const ShaderRecord& record, const ShaderTableRegion& region, uint32_t index,
                     const char* kind) -> Status {
        if (record.localData.size() > localDataBytes)
            return makeError(nameOf(desc) + ": " + kind + " record '" + record.exportName + "' carries " +
                             std::to_string(record.localData.size()) + " bytes of local data, but the state object "
                             "declares localBindings.localDataBytes = " + std::to_string(localDataBytes));
        const uint8_t* handle = handleOf(record.exportName);
        if (!handle)
            return makeError(nameOf(desc) + ": " + kind + " record '" + record.exportName +
                             "' names no raygen/miss/callable export or hit group of the state object");
        uint8_t* dst = image.bytes.data() + region.offset + uint64_t(index) * region.stride;
        std::memcpy(dst, handle, alignment.handleSize);
        if (!record.localData.empty()) std::memcpy(dst + alignment.handleSize, record.localData.data(), record.localData.size());
        return okStatus();
    };
    CAUSTICS_CHECK(write(desc.rayGen, image.layout.rayGen, 0, "raygen"));
    for (uint32_t i = 0; i < desc.missRecords.size(); ++i)
        CAUSTICS_CHECK(write(desc.missRecords[i], image.layout.miss, i, "miss"));
    for (uint32_t i = 0; i < desc.hitGroupRecords.size(); ++i)
        CAUSTICS_CHECK(write(desc.hitGroupRecords[i], image.layout.hitGroup, i, "hit-group"));
    for (uint32_t i = 0; i < desc.callableRecords.size(); ++i)
        CAUSTICS_CHECK(write(desc.callableRecords[i], image.layout.callable, i, "callable"));
    return image;
}

Result<std::shared_ptr<VulkanShaderTable>> VulkanShaderTable::create(VulkanDevice& device, const ShaderTableDesc& desc) {
    if (!desc.stateObject) return makeError(nameOf(desc) + ": no state object");
    const VulkanStateObject& so = *toVk(desc.stateObject);
    const VulkanContext& ctx = device.context();
    ShaderTableAlignment alignment;
    alignment.handleSize = ctx.rayTracingProperties.shaderGroupHandleSize;
    alignment.handleAlignment = ctx.rayTracingProperties.shaderGroupHandleAlignment;
    alignment.baseAlignment = ctx.rayTracingProperties.shaderGroupBaseAlignment;
    alignment.maxStride = ctx.rayTracingProperties.maxShaderGroupStride;
    CAUSTICS_TRY(ShaderTableImage image,
                 buildShaderTableImage(desc, alignment, so.desc().localBindings.localDataBytes,
                                       [&](const std::string& name) { return so.groupHandle(name); }));

    std::shared_ptr<VulkanShaderTable> table(new VulkanShaderTable(desc));
    table->layout_ = image.layout;
    // The buffer's address is only guaranteed to meet its memory alignment, so over-allocate by the
    // base alignment and start the table at the first aligned address (VUID-vkCmdTraceRaysKHR-pRayGenShaderBindingTable-03682).
    const uint64_t base = alignment.baseAlignment;
    auto buffer = device.createBuffer(BufferDesc()
                                          .setByteSize(image.bytes.size() + base)
                                          .setUsage(BufferUsage::ShaderTable | BufferUsage::CopyDest)
                                          .setMemory(MemoryType::DeviceLocal)
                                          .setDebugName(desc.debugName.empty() ? "shader table" : desc.debugName));
    if (!buffer) return buffer.error();
    table->buffer_ = buffer.value();
    const uint64_t address = alignUp(buffer.value()->deviceAddress(), base);
    const uint64_t start = address - buffer.value()->deviceAddress();

    // Device-local for trace performance, filled once at creation with vkCmdUpdateBuffer (at most
    // 65536 bytes per call, spec "Updating Buffers"; tables are small, so no staging buffer is needed).
    Status uploaded = device.executeImmediate([&](VulkanCommandList& list) {
        list.barrier(BufferBarrier{table->buffer_, ResourceState::Undefined, ResourceState::CopyDest});
        constexpr uint64_t kMaxUpdate = 65536;
        for (uint64_t done = 0; done < image.bytes.size(); done += kMaxUpdate) {
            const uint64_t bytes = std::min<uint64_t>(kMaxUpdate, image.bytes.size() - done);
            list.context().fn.vkCmdUpdateBuffer(list.commandBuffer(), toVk(table->buffer_)->handle(), start + done, bytes,
                              image.bytes.data() + done);
        }
        list.barrier(BufferBarrier{table->buffer_, ResourceState::CopyDest, ResourceState::ShaderTable});
    });
    if (!uploaded) return uploaded.error();

    const ShaderTableRegion* regions[4] = {&image.layout.rayGen, &image.layout.miss, &image.layout.hitGroup,
                                           &image.layout.callable};
    for (int i = 0; i < 4; ++i) {
        if (regions[i]->count == 0) continue;   // an empty region is all zero (address, stride and size)
        table->regions_[i] = {address + regions[i]->offset, regions[i]->stride, regions[i]->size};
    }
    return table;
}

Result<ShaderTableHandle> VulkanDevice::createShaderTable(const ShaderTableDesc& desc) {
    auto table = VulkanShaderTable::create(*this, desc);
    if (!table) return table.error();
    return ShaderTableHandle(table.value());
}

}  // namespace caustics::rhi::vulkan
