#include "caustics_view.h"

#include <cstring>

namespace caustics {

CausticsView::CausticsView(std::unique_ptr<Impl> impl) : impl_(std::move(impl)) {}
CausticsView::~CausticsView() = default;

Result<std::unique_ptr<CausticsView::Impl>> CausticsView::Impl::create(rhi::IDevice& device,
                                                                       const rhi::BindingLayoutHandle& cameraLayout,
                                                                       uint32_t framesInFlight) {
    auto v = std::make_unique<Impl>();
    for (uint32_t i = 0; i < framesInFlight; ++i) {
        CAUSTICS_TRY(rhi::BufferHandle buffer, device.createBuffer(rhi::BufferDesc()
                                                                       .setByteSize(sizeof(CameraConstants))
                                                                       .setUsage(rhi::BufferUsage::Constant)
                                                                       .setMemory(rhi::MemoryType::Upload)
                                                                       .setDebugName("camera constants")));
        if (!buffer->mappedData()) return makeError("CausticsView: the camera buffer is not host-visible");
        CAUSTICS_TRY(rhi::BindingSetHandle set,
                     device.createBindingSet(rhi::BindingSetDesc().add(rhi::BindingSetItem::constantBuffer(0, buffer)),
                                             cameraLayout));
        v->cameraBuffers.push_back(buffer);
        v->cameraSets.push_back(set);
    }
    return v;
}

std::optional<glm::mat4> CausticsView::Impl::previousViewProj(const CameraView& camera, bool cameraCut) const {
    if (cameraCut) return std::nullopt;
    if (camera.prevViewProj) return camera.prevViewProj;
    return lastViewProj;
}

void CausticsView::Impl::addBeginPass(rg::RenderGraph& graph, const CameraConstants& camera, uint32_t slot) {
    graph.addPass("view.begin", [&](rg::PassBuilder& b) {
        b.setSideEffects();
        Impl* self = this;
        rhi::BufferHandle buffer = cameraBuffers[slot];
        return [self, buffer, camera](rg::PassContext&) {
            // Host-visible memory: the write is visible to the GPU from the next submit on (Vulkan
            // spec 7.9); frame n - framesInFlight, the slot's last user, has finished (host contract).
            std::memcpy(buffer->mappedData(), &camera, sizeof(CameraConstants));
            self->lastViewProj = camera.viewProj;
        };
    });
}

}  // namespace caustics
