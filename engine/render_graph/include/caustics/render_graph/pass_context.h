#pragma once
// Execution phase: what a pass's record callback sees. Resources resolve only if the pass declared
// them; anything else is an error naming the pass and the resource (logged, and execute() fails).
#include <string>
#include <vector>

#include "caustics/render_graph/resource_handle.h"
#include "caustics/rhi/accel_struct.h"
#include "caustics/rhi/command_list.h"
#include "caustics/rhi/device.h"

namespace caustics::rg {

struct GraphDesc;
struct PassDecl;

// Physical objects of every graph resource for one execution (index = resource slot).
struct PhysicalResources {
    std::vector<rhi::TextureHandle> textures;
    std::vector<rhi::BufferHandle> buffers;
    std::vector<rhi::AccelStructHandle> accelStructs;
};

class PassContext {
public:
    PassContext(rhi::IDevice* device, rhi::ICommandList& commandList, const GraphDesc& graph, uint32_t pass,
                const PhysicalResources& resources)
        : device_(device), commandList_(commandList), graph_(graph), pass_(pass), resources_(resources) {}

    rhi::ICommandList& commandList() { return commandList_; }
    rhi::ICommandList& cmd() { return commandList_; }
    // The device executing the graph (null in device-free tests).
    rhi::IDevice* device() { return device_; }

    const rhi::TextureHandle& texture(RgTexture handle);
    const rhi::BufferHandle& buffer(RgBuffer handle);
    const rhi::AccelStructHandle& accelStruct(RgAccelStruct handle);

    bool failed() const { return !error_.empty(); }
    const std::string& error() const { return error_; }

private:
    bool declared(ResourceKind kind, uint32_t index, const char* what);

    rhi::IDevice* device_;
    rhi::ICommandList& commandList_;
    const GraphDesc& graph_;
    uint32_t pass_;
    const PhysicalResources& resources_;
    std::string error_;
};

}  // namespace caustics::rg
