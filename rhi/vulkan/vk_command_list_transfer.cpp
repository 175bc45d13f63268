// Copies, fills, uploads and clears.
#include <algorithm>
#include <cstring>
#include <string>

#include "../core/texture_copy_check.h"
#include "vk_buffer.h"
#include "vk_command_list.h"
#include "vk_texture.h"

namespace caustics::rhi::vulkan {

// vkCmdUpdateBuffer is limited to 65536 bytes in multiples of 4 (spec vkCmdUpdateBuffer VUs).
static constexpr uint64_t kInlineUpdateLimit = 65536;

void VulkanCommandList::writeBuffer(const BufferHandle& dst, const void* data, uint64_t bytes, uint64_t dstOffset) {
    if (bytes == 0) return;
    VulkanBuffer* d = toVk(dst);
    retain(dst);
    if (bytes <= kInlineUpdateLimit && bytes % 4 == 0 && dstOffset % 4 == 0) {
        context().fn.vkCmdUpdateBuffer(commandBuffer_, d->handle(), dstOffset, bytes, data);
        return;
    }
    BufferHandle staging = allocateTransient(BufferDesc()
                                                 .setByteSize(bytes)
                                                 .setUsage(BufferUsage::CopySource)
                                                 .setMemory(MemoryType::Upload)
                                                 .setDebugName("writeBuffer staging"));
    if (!staging) return;
    std::memcpy(staging->mappedData(), data, bytes);
    VkBufferCopy region{0, dstOffset, bytes};
    context().fn.vkCmdCopyBuffer(commandBuffer_, toVk(staging)->handle(), d->handle(), 1, &region);
}

void VulkanCommandList::copyBuffer(const BufferHandle& dst, uint64_t dstOffset, const BufferHandle& src,
                                   uint64_t srcOffset, uint64_t bytes) {
    if (bytes == 0) return;
    VkBufferCopy region{srcOffset, dstOffset, bytes};
    context().fn.vkCmdCopyBuffer(commandBuffer_, toVk(src)->handle(), toVk(dst)->handle(), 1, &region);
    retain(dst);
    retain(src);
}

void VulkanCommandList::fillBuffer(const BufferHandle& dst, uint32_t value, uint64_t offset, uint64_t bytes) {
    // ~0ull = to the end; Vulkan rounds VK_WHOLE_SIZE down to a multiple of 4 itself.
    context().fn.vkCmdFillBuffer(commandBuffer_, toVk(dst)->handle(), offset, bytes == ~0ull ? VK_WHOLE_SIZE : bytes, value);
    retain(dst);
}

namespace {
VkBufferImageCopy textureRegion(const VulkanTexture& t, uint32_t layer, uint32_t mip, uint64_t bufferOffset) {
    VkBufferImageCopy region{};
    region.bufferOffset = bufferOffset;
    region.bufferRowLength = 0;     // tightly packed
    region.bufferImageHeight = 0;
    VkImageAspectFlags aspect = t.aspect();
    if (aspect & VK_IMAGE_ASPECT_DEPTH_BIT) aspect = VK_IMAGE_ASPECT_DEPTH_BIT;
    region.imageSubresource = {aspect, mip, layer, 1};
    region.imageExtent = {std::max(1u, t.desc().width >> mip), std::max(1u, t.desc().height >> mip), 1};
    return region;
}
}  // namespace

void VulkanCommandList::writeTexture(const TextureHandle& dst, uint32_t layer, uint32_t mip, const void* data,
                                     uint64_t bytes) {
    VulkanTexture* t = toVk(dst);
    const TextureDesc& d = t->desc();
    const uint64_t expected = uint64_t(std::max(1u, d.width >> mip)) * std::max(1u, d.height >> mip) *
                              formatInfo(d.format).bytesPerPixel;
    if (bytes < expected) {
        recordError("vulkan: writeTexture '" + d.debugName + "' got " + std::to_string(bytes) + " bytes, needs " +
                    std::to_string(expected));
        return;
    }
    BufferHandle staging = allocateTransient(BufferDesc()
                                                 .setByteSize(expected)
                                                 .setUsage(BufferUsage::CopySource)
                                                 .setMemory(MemoryType::Upload)
                                                 .setDebugName("writeTexture staging"));
    if (!staging) return;
    std::memcpy(staging->mappedData(), data, expected);
    VkBufferImageCopy region = textureRegion(*t, layer, mip, 0);
    context().fn.vkCmdCopyBufferToImage(commandBuffer_, toVk(staging)->handle(), t->handle(), VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL,
                           1, &region);
    retain(dst);
}

void VulkanCommandList::copyTextureToBuffer(const BufferHandle& dst, uint64_t dstOffset, const TextureHandle& src,
                                            uint32_t layer, uint32_t mip) {
    VulkanTexture* t = toVk(src);
    VkBufferImageCopy region = textureRegion(*t, layer, mip, dstOffset);
    context().fn.vkCmdCopyImageToBuffer(commandBuffer_, t->handle(), VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL, toVk(dst)->handle(), 1,
                           &region);
    retain(dst);
    retain(src);
}

void VulkanCommandList::copyTexture(const TextureHandle& dst, const TextureRegion& dstRegion, const TextureHandle& src,
                                    const TextureRegion& srcRegion) {
    VulkanTexture* d = toVk(dst);
    VulkanTexture* s = toVk(src);
    auto extent = checkTextureCopy(d->desc(), dstRegion, s->desc(), srcRegion);
    if (!extent) return recordError("vulkan: " + extent.message());
    auto copyAspect = [](const VulkanTexture& t) {
        VkImageAspectFlags aspect = t.aspect();
        return (aspect & VK_IMAGE_ASPECT_DEPTH_BIT) ? VkImageAspectFlags(VK_IMAGE_ASPECT_DEPTH_BIT) : aspect;
    };
    VkImageCopy region{};
    region.srcSubresource = {copyAspect(*s), srcRegion.mip, srcRegion.layer, 1};
    region.srcOffset = {int32_t(srcRegion.x), int32_t(srcRegion.y), 0};
    region.dstSubresource = {copyAspect(*d), dstRegion.mip, dstRegion.layer, 1};
    region.dstOffset = {int32_t(dstRegion.x), int32_t(dstRegion.y), 0};
    region.extent = {extent->width, extent->height, 1};
    context().fn.vkCmdCopyImage(commandBuffer_, s->handle(), VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL, d->handle(),
                   VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL, 1, &region);
    retain(dst);
    retain(src);
}

void VulkanCommandList::clearTextureFloat(const TextureHandle& texture, const float value[4]) {
    VulkanTexture* t = toVk(texture);
    VkImageSubresourceRange range{t->aspect(), 0, VK_REMAINING_MIP_LEVELS, 0, VK_REMAINING_ARRAY_LAYERS};
    if (formatInfo(t->desc().format).isDepth) {
        VkClearDepthStencilValue clear{value[0], 0};
        context().fn.vkCmdClearDepthStencilImage(commandBuffer_, t->handle(), VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL, &clear, 1,
                                    &range);
    } else {
        VkClearColorValue clear{};
        std::memcpy(clear.float32, value, sizeof(clear.float32));
        context().fn.vkCmdClearColorImage(commandBuffer_, t->handle(), VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL, &clear, 1, &range);
    }
    retain(texture);
}

void VulkanCommandList::clearTextureUint(const TextureHandle& texture, const uint32_t value[4]) {
    VulkanTexture* t = toVk(texture);
    VkImageSubresourceRange range{t->aspect(), 0, VK_REMAINING_MIP_LEVELS, 0, VK_REMAINING_ARRAY_LAYERS};
    // Integer formats take the bits as uint32; float formats take the same bits reinterpreted.
    VkClearColorValue clear{};
    std::memcpy(clear.uint32, value, sizeof(clear.uint32));
    context().fn.vkCmdClearColorImage(commandBuffer_, t->handle(), VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL, &clear, 1, &range);
    retain(texture);
}

}  // namespace caustics::rhi::vulkan
