// Rasterization with dynamic rendering (Vulkan 1.3 core).
#include "vk_buffer.h"
#include "vk_command_list.h"
#include "vk_pipeline.h"
#include "vk_texture.h"

namespace caustics::rhi::vulkan {

void VulkanCommandList::beginRendering(const RenderingDesc& desc) {
    std::vector<VkRenderingAttachmentInfo> colors;
    for (const ColorAttachment& c : desc.colors) {
        VkRenderingAttachmentInfo a{VK_STRUCTURE_TYPE_RENDERING_ATTACHMENT_INFO};
        a.imageView = toVk(c.texture)->layerView(c.layer);
        a.imageLayout = VK_IMAGE_LAYOUT_COLOR_ATTACHMENT_OPTIMAL;
        a.loadOp = c.clear ? VK_ATTACHMENT_LOAD_OP_CLEAR : VK_ATTACHMENT_LOAD_OP_LOAD;
        a.storeOp = VK_ATTACHMENT_STORE_OP_STORE;
        // Integer targets clear with the same bits as uint (a uint-valued clear of an id buffer).
        if (formatInfo(c.texture->desc().format).isInteger)
            for (int i = 0; i < 4; ++i) a.clearValue.color.uint32[i] = uint32_t(c.clearValue[i]);
        else
            for (int i = 0; i < 4; ++i) a.clearValue.color.float32[i] = c.clearValue[i];
        colors.push_back(a);
        retain(c.texture);
    }
    VkRenderingAttachmentInfo depth{VK_STRUCTURE_TYPE_RENDERING_ATTACHMENT_INFO};
    if (desc.depth.texture) {
        depth.imageView = toVk(desc.depth.texture)->layerView(desc.depth.layer);
        depth.imageLayout = VK_IMAGE_LAYOUT_DEPTH_STENCIL_ATTACHMENT_OPTIMAL;
        depth.loadOp = desc.depth.clear ? VK_ATTACHMENT_LOAD_OP_CLEAR : VK_ATTACHMENT_LOAD_OP_LOAD;
        depth.storeOp = VK_ATTACHMENT_STORE_OP_STORE;
        depth.clearValue.depthStencil = {desc.depth.clearDepth, 0};
        retain(desc.depth.texture);
    }
    VkRenderingInfo info{VK_STRUCTURE_TYPE_RENDERING_INFO};
    info.renderArea = {{0, 0}, {desc.width, desc.height}};
    info.layerCount = 1;
    info.colorAttachmentCount = uint32_t(colors.size());
    info.pColorAttachments = colors.data();
    info.pDepthAttachment = desc.depth.texture ? &depth : nullptr;
    context().fn.vkCmdBeginRendering(commandBuffer_, &info);
}

void VulkanCommandList::endRendering() { context().fn.vkCmdEndRendering(commandBuffer_); }

void VulkanCommandList::setGraphicsPipeline(const GraphicsPipelineHandle& pipeline) {
    VulkanGraphicsPipeline* p = toVk(pipeline);
    context().fn.vkCmdBindPipeline(commandBuffer_, VK_PIPELINE_BIND_POINT_GRAPHICS, p->pipeline());
    bindPipelineLayout(p->layout(), VK_PIPELINE_BIND_POINT_GRAPHICS);
    retain(pipeline);
}

void VulkanCommandList::setViewport(float x, float y, float width, float height) {
    VkViewport viewport{x, y, width, height, 0.0f, 1.0f};
    context().fn.vkCmdSetViewport(commandBuffer_, 0, 1, &viewport);
    VkRect2D scissor{{int32_t(x), int32_t(y)}, {uint32_t(width), uint32_t(height)}};
    context().fn.vkCmdSetScissor(commandBuffer_, 0, 1, &scissor);
}

void VulkanCommandList::setVertexBuffer(uint32_t slot, const BufferHandle& buffer, uint64_t offset) {
    VkBuffer b = toVk(buffer)->handle();
    VkDeviceSize o = offset;
    context().fn.vkCmdBindVertexBuffers(commandBuffer_, slot, 1, &b, &o);
    retain(buffer);
}

void VulkanCommandList::setIndexBuffer(const BufferHandle& buffer, uint64_t offset) {
    context().fn.vkCmdBindIndexBuffer(commandBuffer_, toVk(buffer)->handle(), offset, VK_INDEX_TYPE_UINT32);
    retain(buffer);
}

void VulkanCommandList::draw(uint32_t vertexCount, uint32_t instanceCount, uint32_t firstVertex,
                             uint32_t firstInstance) {
    context().fn.vkCmdDraw(commandBuffer_, vertexCount, instanceCount, firstVertex, firstInstance);
}

void VulkanCommandList::drawIndexed(uint32_t indexCount, uint32_t instanceCount, uint32_t firstIndex,
                                    int32_t vertexOffset, uint32_t firstInstance) {
    context().fn.vkCmdDrawIndexed(commandBuffer_, indexCount, instanceCount, firstIndex, vertexOffset, firstInstance);
}

}  // namespace caustics::rhi::vulkan
