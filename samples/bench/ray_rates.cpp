#include "ray_rates.h"

#include "bench_gpu.h"

namespace caustics::bench {

using namespace caustics::rhi;

Result<std::vector<RayRate>> measureRayRates(IDevice& dev, const AccelStructHandle& tlas, RayFrameConstants constants,
                                             uint32_t width, uint32_t height, const BenchOptions& options,
                                             const std::vector<std::string>& rayGens) {
    CAUSTICS_TRY(auto layout, dev.createBindingLayout(BindingLayoutDesc()
                                                           .setVisibility(ShaderStage::AllRayTracing)
                                                           .add(0, BindingType::AccelStruct)
                                                           .add(1, BindingType::StorageBufferRW)));
    StateObjectDesc soDesc;
    soDesc.libraries = {benchShaderLibrary("primary.rgen", "primary", ShaderStage::RayGen),
                        benchShaderLibrary("incoherent.rgen", "incoherent", ShaderStage::RayGen),
                        benchShaderLibrary("rays.rmiss", "miss", ShaderStage::Miss),
                        benchShaderLibrary("rays.rchit", "closestHit", ShaderStage::ClosestHit)};
    soDesc.hitGroups.push_back({"hit", HitGroupType::Triangles, "closestHit", "", ""});
    soDesc.maxPayloadBytes = 4;
    soDesc.globalBindings.layouts = {layout};
    soDesc.globalBindings.pushConstantBytes = sizeof(RayFrameConstants);
    soDesc.debugName = "rays bench";
    CAUSTICS_TRY(auto so, dev.createStateObject(soDesc));

    const uint64_t rays = uint64_t(width) * height;
    CAUSTICS_TRY(auto out, dev.createBuffer(BufferDesc().setByteSize(rays * 4).setDebugName("hit distances")));
    CAUSTICS_TRY(auto readback, dev.createBuffer(BufferDesc().setByteSize(rays * 4).setUsage(BufferUsage::CopyDest)
                                                     .setMemory(MemoryType::Readback).setDebugName("hit readback")));
    CAUSTICS_TRY(auto set, dev.createBindingSet(BindingSetDesc()
                                                    .add(BindingSetItem::accelStructItem(0, tlas))
                                                    .add(BindingSetItem::storageBuffer(1, out)),
                                                layout));
    CAUSTICS_CHECK(runOnce(dev, [&](ICommandList& cmd) {
        cmd.barrier(BufferBarrier{out, ResourceState::Undefined, ResourceState::UnorderedAccess});
    }));

    std::vector<RayRate> results;
    for (const std::string& rayGen : rayGens) {
        CAUSTICS_TRY(auto table,
                     dev.createShaderTable(ShaderTableDesc{so}.setRayGen(rayGen).addMiss("miss").addHitGroup("hit")));
        CAUSTICS_TRY(auto ms, timeFrames(dev, options.warmupFrames, options.frames, [&](ICommandList& cmd, uint32_t frame) {
            constants.frame = frame;
            cmd.setRayTracingState(so, table);
            cmd.setBindingSet(0, set);
            cmd.setPushConstants(&constants, sizeof(constants));
            cmd.dispatchRays(width, height);
            // Write-after-write on the output between frames.
            cmd.barrier(BufferBarrier{out, ResourceState::UnorderedAccess, ResourceState::UnorderedAccess});
        }));
        CAUSTICS_CHECK(runOnce(dev, [&](ICommandList& cmd) {
            cmd.barrier(BufferBarrier{out, ResourceState::UnorderedAccess, ResourceState::CopySource});
            cmd.barrier(BufferBarrier{readback, ResourceState::Undefined, ResourceState::CopyDest});
            cmd.copyBuffer(readback, 0, out, 0, rays * 4);
            cmd.barrier(BufferBarrier{out, ResourceState::CopySource, ResourceState::UnorderedAccess});
        }));
        std::vector<float> t(rays);
        CAUSTICS_CHECK(dev.readBuffer(readback, t.data(), rays * 4));
        uint64_t hits = 0;
        for (float v : t) hits += v >= 0.0f ? 1 : 0;
        results.push_back({rayGen, rays, median(ms), double(hits) / double(rays)});
    }
    return results;
}

}  // namespace caustics::bench
