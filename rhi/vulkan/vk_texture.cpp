#include "vk_texture.h"

namespace caustics::rhi::vulkan {
namespace {

VkImageUsageFlags toVkImageUsage(TextureUsage usage, Format format) {
    VkImageUsageFlags flags = VK_IMAGE_USAGE_TRANSFER_SRC_BIT | VK_IMAGE_USAGE_TRANSFER_DST_BIT;
    if (hasAny(usage, TextureUsage::Sampled)) flags |= VK_IMAGE_USAGE_SAMPLED_BIT;
    if (hasAny(usage, TextureUsage::Storage)) flags |= VK_IMAGE_USAGE_STORAGE_BIT;
    if (hasAny(usage, TextureUsage::RenderTarget)) flags |= VK_IMAGE_USAGE_COLOR_ATTACHMENT_BIT;
    if (hasAny(usage, TextureUsage::DepthStencil) || formatInfo(format).isDepth)
        flags |= VK_IMAGE_USAGE_DEPTH_STENCIL_ATTACHMENT_BIT;
    return flags;
}

}  // namespace

Result<std::shared_ptr<VulkanTexture>> VulkanTexture::create(const ContextPtr& context, const TextureDesc& desc) {
    const VulkanContext& ctx = *context;
    std::shared_ptr<VulkanTexture> texture(new VulkanTexture(context, desc));
    texture->format_ = toVkFormat(desc.format);
    if (texture->format_ == VK_FORMAT_UNDEFINED || desc.format == Format::RGB32_FLOAT)
        return makeError("vulkan: texture '" + desc.debugName + "' has unsupported format " +
                         formatInfo(desc.format).name);
    if (desc.dimension == TextureDimension::TextureCube && desc.arrayLayers % 6 != 0)
        return makeError("vulkan: cube texture '" + desc.debugName + "' needs a multiple of 6 layers");

    VkImageCreateInfo info{VK_STRUCTURE_TYPE_IMAGE_CREATE_INFO};
    if (desc.dimension == TextureDimension::TextureCube) info.flags |= VK_IMAGE_CREATE_CUBE_COMPATIBLE_BIT;
    info.imageType = VK_IMAGE_TYPE_2D;
    info.format = texture->format_;
    info.extent = {desc.width, desc.height, 1};
    info.mipLevels = desc.mipLevels;
    info.arrayLayers = desc.arrayLayers;
    info.samples = VK_SAMPLE_COUNT_1_BIT;
    info.tiling = VK_IMAGE_TILING_OPTIMAL;
    info.usage = toVkImageUsage(desc.usage, desc.format);
    info.sharingMode = VK_SHARING_MODE_EXCLUSIVE;
    info.initialLayout = VK_IMAGE_LAYOUT_UNDEFINED;
    VkResult r = ctx.fn.vkCreateImage(ctx.device, &info, nullptr, &texture->image_);
    if (r != VK_SUCCESS) return vkError(r, "vkCreateImage", desc.debugName);
    ctx.setName(VK_OBJECT_TYPE_IMAGE, texture->image_, desc.debugName);
    if (desc.isVirtual) return texture;

    auto allocation = ctx.allocator->allocate(texture->requirements(), MemoryType::DeviceLocal, true, desc.debugName);
    if (!allocation) return allocation.error();
    texture->allocation_ = allocation.value();
    r = ctx.fn.vkBindImageMemory(ctx.device, texture->image_, texture->allocation_.memory, texture->allocation_.offset);
    if (r != VK_SUCCESS) return vkError(r, "vkBindImageMemory", desc.debugName);
    return texture;
}

std::shared_ptr<VulkanTexture> VulkanTexture::wrap(const ContextPtr& context, const TextureDesc& desc, VkImage image,
                                                   VkFormat format) {
    std::shared_ptr<VulkanTexture> texture(new VulkanTexture(context, desc));
    texture->image_ = image;
    texture->format_ = format;
    texture->ownsImage_ = false;
    return texture;
}

VulkanTexture::~VulkanTexture() {
    ContextPtr ctx = context_;
    VkImage image = ownsImage_ ? image_ : VK_NULL_HANDLE;
    MemoryAllocation allocation = allocation_;
    std::vector<VkImageView> views;
    for (auto& [key, view] : views_) views.push_back(view);
    ctx->deferDestroy([ctx, image, allocation, views] {
        for (VkImageView v : views) ctx->fn.vkDestroyImageView(ctx->device, v, nullptr);
        if (image != VK_NULL_HANDLE) ctx->fn.vkDestroyImage(ctx->device, image, nullptr);
        ctx->allocator->free(allocation);
    });
}

VkMemoryRequirements VulkanTexture::requirements() const {
    VkMemoryRequirements req{};
    context_->fn.vkGetImageMemoryRequirements(context_->device, image_, &req);
    return req;
}

Status VulkanTexture::bindMemory(VkDeviceMemory memory, uint64_t offset) {
    VkResult r = context_->fn.vkBindImageMemory(context_->device, image_, memory, offset);
    if (r != VK_SUCCESS) return vkError(r, "vkBindImageMemory", desc_.debugName);
    return okStatus();
}

Result<VkImageView> VulkanTexture::makeView(VkImageViewType type, uint32_t baseLayer, uint32_t layers,
                                            uint32_t baseMip, uint32_t mips) {
    VkImageViewCreateInfo info{VK_STRUCTURE_TYPE_IMAGE_VIEW_CREATE_INFO};
    info.image = image_;
    info.viewType = type;
    info.format = format_;
    // Sampling and attachments of a depth/stencil image use the depth aspect only.
    VkImageAspectFlags viewAspect = aspect();
    if (viewAspect & VK_IMAGE_ASPECT_DEPTH_BIT) viewAspect = VK_IMAGE_ASPECT_DEPTH_BIT;
    info.subresourceRange = {viewAspect, baseMip, mips, baseLayer, layers};
    VkImageView view = VK_NULL_HANDLE;
    VkResult r = context_->fn.vkCreateImageView(context_->device, &info, nullptr, &view);
    if (r != VK_SUCCESS) return vkError(r, "vkCreateImageView", desc_.debugName);
    context_->setName(VK_OBJECT_TYPE_IMAGE_VIEW, view, desc_.debugName);
    return view;
}

VkImageView VulkanTexture::sampledView() {
    std::lock_guard lock(viewMutex_);
    auto [it, inserted] = views_.emplace(0ull << 48, VK_NULL_HANDLE);
    if (inserted) {
        VkImageViewType type = desc_.dimension == TextureDimension::TextureCube
                                   ? (desc_.arrayLayers > 6 ? VK_IMAGE_VIEW_TYPE_CUBE_ARRAY : VK_IMAGE_VIEW_TYPE_CUBE)
                               : desc_.dimension == TextureDimension::Texture2DArray ? VK_IMAGE_VIEW_TYPE_2D_ARRAY
                                                                                     : VK_IMAGE_VIEW_TYPE_2D;
        auto view = makeView(type, 0, desc_.arrayLayers, 0, desc_.mipLevels);
        it->second = view ? view.value() : VK_NULL_HANDLE;
    }
    return it->second;
}

VkImageView VulkanTexture::storageView() {
    std::lock_guard lock(viewMutex_);
    auto [it, inserted] = views_.emplace(1ull << 48, VK_NULL_HANDLE);
    if (inserted) {
        VkImageViewType type = desc_.dimension == TextureDimension::Texture2D ? VK_IMAGE_VIEW_TYPE_2D
                                                                              : VK_IMAGE_VIEW_TYPE_2D_ARRAY;
        auto view = makeView(type, 0, desc_.arrayLayers, 0, 1);
        it->second = view ? view.value() : VK_NULL_HANDLE;
    }
    return it->second;
}

VkImageView VulkanTexture::layerView(uint32_t layer, uint32_t mip) {
    std::lock_guard lock(viewMutex_);
    auto [it, inserted] = views_.emplace((2ull << 48) | (uint64_t(layer) << 16) | mip, VK_NULL_HANDLE);
    if (inserted) {
        auto view = makeView(VK_IMAGE_VIEW_TYPE_2D, layer, 1, mip, 1);
        it->second = view ? view.value() : VK_NULL_HANDLE;
    }
    return it->second;
}

}  // namespace caustics::rhi::vulkan
