#include "caustics/render_graph/pass_context.h"

#include "caustics/render_graph/graph_desc.h"
#include "caustics/rhi/log.h"

namespace caustics::rg {

bool PassContext::declared(ResourceKind kind, uint32_t index, const char* what) {
    const PassDecl& pass = graph_.passes[pass_];
    if (index < graph_.resources.size() && graph_.resources[index].kind == kind)
        for (const AccessDecl& a : pass.accesses)
            if (a.resource == index) return true;
    std::string name = index < graph_.resources.size() ? "'" + graph_.resources[index].name + "'" : "(invalid handle)";
    std::string message = "render graph: pass '" + pass.name + "' asked for " + what + " " + name +
                          " that its setup did not declare";
    log(LogLevel::Error, message);
    if (error_.empty()) error_ = std::move(message);
    return false;
}

const rhi::TextureHandle& PassContext::texture(RgTexture h) {
    static const rhi::TextureHandle kNone;
    return declared(ResourceKind::Texture, h.index, "texture") ? resources_.textures[h.index] : kNone;
}

const rhi::BufferHandle& PassContext::buffer(RgBuffer h) {
    static const rhi::BufferHandle kNone;
    return declared(ResourceKind::Buffer, h.index, "buffer") ? resources_.buffers[h.index] : kNone;
}

const rhi::AccelStructHandle& PassContext::accelStruct(RgAccelStruct h) {
    static const rhi::AccelStructHandle kNone;
    return declared(ResourceKind::AccelStruct, h.index, "acceleration structure") ? resources_.accelStructs[h.index]
                                                                                   : kNone;
}

}  // namespace caustics::rg
