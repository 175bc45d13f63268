#include "caustics_view.h"

#include <cstring>
#include <string>

#include "caustics/rhi/log.h"

namespace caustics {

CausticsView::CausticsView(std::unique_ptr<Impl> impl) : impl_(std::move(impl)) {}
CausticsView::~CausticsView() = default;

Result<std::unique_ptr<CausticsView::Impl>> CausticsView::Impl::create(rhi::IDevice& device,
                                                                       const rhi::BindingLayoutHandle& cameraLayout,
                                                                       uint32_t framesInFlight,
                                                                       const std::shared_ptr<ViewRegistry>& registry) {
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
    {
        std::lock_guard lock(registry->mutex);
        v->id = registry->nextId++;
    }
    v->registry = registry;
    v->history.viewId = v->id;
    return v;
}

CausticsView::Impl::~Impl() {
    if (std::shared_ptr<ViewRegistry> r = registry.lock()) {
        std::lock_guard lock(r->mutex);
        r->destroyed.push_back(id);
    }
}

std::shared_ptr<const CameraConstants> CausticsView::Impl::addBeginPass(rg::RenderGraph& graph,
                                                                        const CameraConstants& camera, uint32_t slot,
                                                                        const BeginPassInputs& inputs) {
    auto executed = std::make_shared<CameraConstants>(camera);
    graph.addPass("view.begin", [&](rg::PassBuilder& b) {
        b.setSideEffects();
        Impl* self = this;
        rhi::BufferHandle buffer = cameraBuffers[slot];
        return [self, buffer, executed, inputs](rg::PassContext&) {
            CameraConstants& c = *executed;
            // frameIndex seeds the photons: a host handing its frame-in-flight slot here repeats them every
            // framesInFlight frames. Checked when frames execute (a graph built only to be compiled does
            // not count); a restart of the count comes with a camera cut (resetHistory). The error is
            // logged, and the render graph returns it from execute().
            if (self->lastExecutedFrame && inputs.frameIndex < *self->lastExecutedFrame && !inputs.cameraCut)
                log(LogLevel::Error, "CausticsModule: FrameInputs::frameIndex " + std::to_string(inputs.frameIndex) +
                                         " is below the view's last executed frame " +
                                         std::to_string(*self->lastExecutedFrame) +
                                         ": it is the frame number, which seeds the photons and must not decrease "
                                         "(restart it with resetHistory); the frame-in-flight slot goes in "
                                         "FrameInputs::frameSlot");
            self->lastExecutedFrame = inputs.frameIndex;
            const glm::uvec2 size(c.frame.x, c.frame.y);
            if (inputs.cameraCut) {
                c.prevViewProj = c.viewProj;   // no previous frame: no motion
            } else if (inputs.hostPrevViewProj) {
                // The history's pixels were drawn with last frame's jitter: reproject into those.
                c.prevViewProj = inputs.unjitteredPrev
                                     ? jitterClipMatrix(*inputs.hostPrevViewProj, self->lastJitterPixels, size.x, size.y)
                                     : *inputs.hostPrevViewProj;
            } else {
                c.prevViewProj = self->lastViewProj.value_or(c.viewProj);
            }
            // Host-visible memory: the write is visible to the GPU from the next submit on (Vulkan
            // spec 7.9); frame n - framesInFlight, the slot's last user, has finished (host contract).
            std::memcpy(buffer->mappedData(), &c, sizeof(CameraConstants));
            self->lastViewProj = c.viewProj;
            self->lastJitterPixels = glm::vec2(c.eye.w, c.up.w);   // CameraConstants: jitter in eye.w, up.w
        };
    });
    return executed;
}

}  // namespace caustics
