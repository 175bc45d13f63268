#pragma once
// The render graph (frame graph). Each frame: reset(), import host resources, addPass(...) for every
// pass (setup runs at once and returns the record callback), mark outputs, execute(). The graph, not
// the passes, culls, orders, allocates and aliases transients, and records every barrier.
//
//   RgTexture out = graph.importTexture("output", hostTex, ShaderResource, ShaderResource);
//   graph.addPass("fill", [&](PassBuilder& b) {
//       RgTexture t = b.createTexture("tmp", desc);
//       t = b.write(t, Access::StorageWrite);
//       return [=](PassContext& ctx) { ... ctx.texture(t) ... ctx.cmd().dispatch(...); };
//   });
//   graph.markOutput(out);
//   graph.execute(device, cmd);   // cmd is begun; the host ends and submits it
#include <functional>
#include <initializer_list>
#include <memory>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "caustics/render_graph/compiled_plan.h"
#include "caustics/render_graph/graph_desc.h"
#include "caustics/render_graph/pass_builder.h"
#include "caustics/render_graph/pass_context.h"
#include "caustics/render_graph/pass_timings.h"
#include "caustics/rhi/device.h"

namespace caustics::rg {

using PassExecuteFn = std::function<void(PassContext&)>;
using PassSetupFn = std::function<PassExecuteFn(PassBuilder&)>;

class RenderGraph {
public:
    RenderGraph();
    ~RenderGraph();
    RenderGraph(const RenderGraph&) = delete;
    RenderGraph& operator=(const RenderGraph&) = delete;

    // Setup. addPass runs `setup` immediately; it returns the callback that records the pass.
    uint32_t addPass(std::string name, const PassSetupFn& setup);
    // Imported resources: the host's object, the state it is in now and the state to leave it in.
    // Importing an object again in the same graph returns the same resource at its latest version
    // (`current` is then ignored: the graph knows the state; the later `final` wins).
    RgTexture importTexture(std::string name, rhi::TextureHandle texture, rhi::ResourceState current,
                            rhi::ResourceState final);
    RgBuffer importBuffer(std::string name, rhi::BufferHandle buffer, rhi::ResourceState current,
                          rhi::ResourceState final);
    RgAccelStruct importAccelStruct(std::string name, rhi::AccelStructHandle as, rhi::ResourceState current,
                                    rhi::ResourceState final);
    // The host reads this resource afterwards: its producers are kept. For a transient, `final` is the
    // state it is left in (Undefined = the state of its last use); for an import, its final state rules.
    void markOutput(RgTexture texture, rhi::ResourceState final = rhi::ResourceState::Undefined);
    void markOutput(RgBuffer buffer, rhi::ResourceState final = rhi::ResourceState::Undefined);
    void markOutput(RgAccelStruct as);
    // A library that adds passes for the host (the caustics module) names what it hands back: compile()
    // fails, naming them and `owner`, when none of `anyOf` reaches the host: the producer of its latest
    // version is culled and no kept pass reads it (the graph would cull every pass that makes them
    // without a word: a black image). Invalid handles in `anyOf` are skipped.
    void expectConsumer(std::initializer_list<RgTexture> anyOf, std::string owner);

    // Compile without a device (memory sizes from `sizer`); execute() compiles again with the device.
    Status compile(const IMemorySizer& sizer);
    const CompiledPlan* plan() const { return plan_ ? &*plan_ : nullptr; }
    const GraphDesc& desc() const { return desc_; }

    // Creates/reuses transients, records barriers and passes (with GPU timestamps) into `commandList`,
    // which the caller has begun and will end and submit.
    Status execute(rhi::IDevice& device, rhi::ICommandList& commandList);
    // Physical object of a resource after execute() (for outputs the host reads).
    rhi::TextureHandle texture(RgTexture handle) const;
    rhi::BufferHandle buffer(RgBuffer handle) const;

    // Reads timestamps of finished frames into the per-pass medians. execute() calls it; a host that
    // waited for the frame's fence may call it to see that frame's times at once.
    void collectTimings(rhi::IDevice& device);
    void setTimingWindow(uint32_t frames) { timings_.setWindow(frames); }
    std::optional<double> passTimeMs(std::string_view pass) const { return timings_.medianMs(pass); }
    const PassTimings& timings() const { return timings_; }

    // Forgets this frame's passes and resources; keeps transient memory, timestamps and timings.
    void reset();

    std::string printText() const;
    std::string printGraphviz() const;

    struct ExecutionState;   // opaque: state kept between frames (src/execution_state.h)

private:
    friend class PassBuilder;
    uint32_t addResource(ResourceDecl decl);
    void setupError(std::string message);
    Status realizeTransients(rhi::IDevice& device);

    GraphDesc desc_;
    std::vector<PassExecuteFn> executes_;
    PhysicalResources imported_;
    std::optional<CompiledPlan> plan_;
    std::string setupError_;
    PassTimings timings_;
    std::unique_ptr<ExecutionState> exec_;
};

}  // namespace caustics::rg
