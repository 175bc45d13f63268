#include "live_scene.h"

#include <algorithm>
#include <cstring>
#include <memory>
#include <string>

#include "caustics/gpu_light.h"

namespace caustics {

// One frame-in-flight slot: its tables, its TLAS and what was last written into them (the update pass
// compares, so a static scene costs no copy and no TLAS build).
struct LiveScene::Slot {
    SceneBindings bindings;
    SceneTables tables;   // the module's own (geometry from the GpuScene)
    SceneTables bound;    // what bindings.set binds (own tables or the host's)
    uint64_t materialBytes = 0, instanceBytes = 0, lightBytes = 0;
    uint32_t tlasCapacity = 0;
    std::vector<uint8_t> writtenMaterials, writtenInstances, writtenLights, writtenTlas;
};

namespace {

// The CPU half of one frame's update: the bytes of each table and the TLAS instances.
struct PackedFrame {
    std::vector<uint8_t> materials, instances, lights, tlas;
    uint32_t instanceCount = 0, lightCount = 0;
};

template <typename T>
void appendBytes(std::vector<uint8_t>& out, const T& value) {
    const auto* p = reinterpret_cast<const uint8_t*>(&value);
    out.insert(out.end(), p, p + sizeof(T));
}

// ownTlas: the module builds the TLAS (needs the GpuScene's BLASes); false when the host hands in its own.
Result<PackedFrame> packFrame(const scene::Scene& scene, const scene::GpuScene& gpu, bool ownTlas) {
    if (scene.instances.empty())
        return makeError("scene '" + scene.name + "' has no mesh instances: nothing to render or trace");
    constexpr size_t kMaxInstances = 1u << 24;   // TLAS instance ids have 24 bits
    if (scene.instances.size() > kMaxInstances)
        return makeError("scene '" + scene.name + "' has " + std::to_string(scene.instances.size()) +
                         " instances, more than the 2^24 a TLAS instance id can index");
    PackedFrame p;
    for (size_t i = 0; i < scene.materials.size(); ++i) {
        const scene::Material& m = scene.materials[i];
        if (m.baseColorTexture >= int32_t(gpu.textures.size()))
            return makeError("scene material " + std::to_string(i) + " ('" + m.name + "') uses texture " +
                             std::to_string(m.baseColorTexture) + ", the GPU scene has " +
                             std::to_string(gpu.textures.size()) + " (textures are fixed at GpuScene::create)");
        appendBytes(p.materials, scene::toGpuMaterial(m));
    }
    if (p.materials.empty()) appendBytes(p.materials, scene::GpuMaterial{});   // never an empty storage buffer
    for (uint32_t i = 0; i < scene.instances.size(); ++i) {
        const scene::Instance& inst = scene.instances[i];
        if (inst.mesh >= scene.meshes.size() || inst.mesh >= gpu.meshRanges.size() ||
            (ownTlas && inst.mesh >= gpu.blases.size()))
            return makeError("scene instance " + std::to_string(i) + " uses mesh " + std::to_string(inst.mesh) +
                             ", the GPU scene has " + std::to_string(gpu.meshRanges.size()) +
                             " meshes (meshes are fixed at GpuScene::create; instances of them may come and go)");
        if (scene.meshes[inst.mesh].material >= std::max<size_t>(scene.materials.size(), 1))
            return makeError("scene mesh " + std::to_string(inst.mesh) + " uses material " +
                             std::to_string(scene.meshes[inst.mesh].material) + ", the scene has " +
                             std::to_string(scene.materials.size()));
        const scene::GpuMeshRange& range = gpu.meshRanges[inst.mesh];
        appendBytes(p.instances, scene::toGpuInstance(scene, inst, range.firstVertex, range.firstIndex));
        if (!ownTlas) continue;
        rhi::InstanceDesc d = scene::makeInstanceDesc(scene, i);
        d.blasAddress = gpu.blases[inst.mesh]->deviceAddress();
        appendBytes(p.tlas, d);
    }
    p.lights = packLightBuffer(scene.lights);
    p.instanceCount = uint32_t(scene.instances.size());
    p.lightCount = uint32_t(scene.lights.size());
    return p;
}

Result<rhi::BufferHandle> hostTable(rhi::IDevice& device, uint64_t bytes, const char* name) {
    CAUSTICS_TRY(rhi::BufferHandle b, device.createBuffer(rhi::BufferDesc().setByteSize(bytes)
                                                              .setUsage(rhi::BufferUsage::Storage)
                                                              .setMemory(rhi::MemoryType::Upload)
                                                              .setDebugName(name)));
    if (!b->mappedData()) return makeError(std::string("LiveScene: the ") + name + " table is not host-visible");
    return b;
}

// Grows a slot's tables to hold `p` (doubling, so a growing scene reallocates rarely).
Status ensureCapacity(rhi::IDevice& device, const scene::GpuScene& gpu, LiveScene::Slot& s, const PackedFrame& p,
                      bool ownTlas) {
    bool rebind = false;
    auto grow = [&](rhi::BufferHandle& buffer, uint64_t& capacity, uint64_t needed, const char* name) -> Status {
        if (buffer && capacity >= needed) return okStatus();
        capacity = std::max(needed, 2 * capacity);
        CAUSTICS_TRY(buffer, hostTable(device, capacity, name));
        rebind = true;
        return okStatus();
    };
    CAUSTICS_CHECK(grow(s.tables.materials, s.materialBytes, p.materials.size(), "live materials"));
    CAUSTICS_CHECK(grow(s.tables.instances, s.instanceBytes, p.instances.size(), "live instances"));
    CAUSTICS_CHECK(grow(s.tables.lights, s.lightBytes, p.lights.size(), "live lights"));
    if (ownTlas && (!s.tables.tlas || s.tlasCapacity < p.instanceCount)) {
        rhi::AccelStructDesc td;
        td.isTopLevel = true;
        td.maxInstances = std::max(p.instanceCount, 2 * s.tlasCapacity);
        td.flags = rhi::AccelBuildFlags::PreferFastTrace;
        td.debugName = "live scene TLAS";
        CAUSTICS_TRY(s.tables.tlas, device.createAccelStruct(td));
        s.tlasCapacity = td.maxInstances;
        rebind = true;
    }
    s.tables.positions = gpu.positions;
    s.tables.vertices = gpu.vertices;
    s.tables.indices = gpu.indices;
    if (!rebind) return okStatus();
    s.writtenMaterials.clear();
    s.writtenInstances.clear();
    s.writtenLights.clear();
    s.writtenTlas.clear();
    return okStatus();
}

// The host's table where it gave one, else the module's.
SceneTables effectiveTables(const SceneTables& own, const HostSceneTables& host) {
    SceneTables t = own;
    if (host.tlas) t.tlas = host.tlas;
    if (host.positions) t.positions = host.positions;
    if (host.vertices) t.vertices = host.vertices;
    if (host.indices) t.indices = host.indices;
    if (host.materials) t.materials = host.materials;
    if (host.instances) t.instances = host.instances;
    return t;
}

// The host's tables enter the graph in the state the host declares (HostSceneTables::tablesState):
// this pass reads them as ShaderResource, so the graph's barrier before it makes the host's writes
// visible to every shader stage of the passes after it (it declares no kind of work, so the barrier
// blocks all of them), and the final barrier returns them to the host's state once every pass has read
// them (docs/embedding.md "Hand-over states"). The tracing passes bind them through the scene
// bindings, which the graph does not see; this pass is where the graph does.
void addHostTableHandOver(rg::RenderGraph& graph, const HostSceneTables& host) {
    const std::pair<const rhi::BufferHandle*, const char*> tables[] = {
        {&host.positions, "host.positions"}, {&host.vertices, "host.vertices"}, {&host.indices, "host.indices"},
        {&host.materials, "host.materials"}, {&host.instances, "host.instances"}};
    std::vector<rg::RgBuffer> imported;
    for (const auto& [buffer, name] : tables)
        if (*buffer) imported.push_back(graph.importBuffer(name, *buffer, host.tablesState, host.tablesState));
    if (imported.empty()) return;
    graph.addPass("scene.host_tables", [&](rg::PassBuilder& b) {
        for (rg::RgBuffer table : imported) b.read(table, rg::Access::SampledRead);
        b.setSideEffects();
        return [](rg::PassContext&) {};
    });
}

}  // namespace

Result<LiveScene> LiveScene::create(rhi::IDevice& device, const scene::GpuScene& gpuScene, uint32_t framesInFlight) {
    LiveScene l;
    l.device_ = &device;
    l.gpuScene_ = &gpuScene;
    CAUSTICS_TRY(l.layout_, SceneBindings::createLayout(device));
    CAUSTICS_TRY(l.sampler_, device.createSampler(rhi::SamplerDesc().setFilter(rhi::FilterMode::Linear)
                                                      .setAddress(rhi::AddressMode::Repeat)));
    for (uint32_t i = 0; i < framesInFlight; ++i) l.slots_.push_back(std::make_shared<Slot>());
    return l;
}

Result<LiveSceneFrame> LiveScene::addUpdatePass(rg::RenderGraph& graph, const scene::Scene& scene, uint32_t slot,
                                                const HostSceneTables& host) {
    if (slot >= slots_.size()) return makeError("LiveScene: frame slot " + std::to_string(slot) + " out of range");
    CAUSTICS_CHECK(checkHostSceneTables(host, scene));
    if (!gpuScene_->positions && !host.positions)
        return makeError("CausticsModule: the GpuScene was made with uploadGeometry = false, so "
                         "FrameInputs::hostScene must hand in positions, vertices and indices (docs/embedding.md "
                         "\"Host scene tables\")");
    const bool buildTlas = !host.tlas;
    CAUSTICS_TRY(auto packed, packFrame(scene, *gpuScene_, buildTlas));
    std::shared_ptr<Slot> s = slots_[slot];
    CAUSTICS_CHECK(ensureCapacity(*device_, *gpuScene_, *s, packed, buildTlas));
    const SceneTables tables = effectiveTables(s->tables, host);
    if (!s->bindings.set || !(tables == s->bound)) {
        s->bindings.layout = layout_;
        s->bindings.sampler = sampler_;
        s->bindings.lights = tables.lights;
        CAUSTICS_TRY(s->bindings.set, SceneBindings::createSet(*device_, layout_, sampler_, gpuScene_->textures, tables));
        s->bound = tables;
    }
    s->bindings.lightCount = packed.lightCount;

    LiveSceneFrame frame;
    frame.bindings = &s->bindings;
    // Our TLAS is left readable: the graph orders this frame's build after earlier frames' traces and
    // before this frame's (every tracing pass declares the read). The host's is imported as it says.
    frame.tlas = buildTlas ? graph.importAccelStruct("scene.tlas", s->tables.tlas, rhi::ResourceState::AccelStructRead,
                                                     rhi::ResourceState::AccelStructRead)
                           : graph.importAccelStruct("host.tlas", host.tlas, host.tlasState, host.tlasState);
    addHostTableHandOver(graph, host);
    auto data = std::make_shared<PackedFrame>(std::move(packed));
    graph.addPass("scene.update", [&](rg::PassBuilder& b) {
        if (buildTlas) frame.tlas = b.write(frame.tlas, rg::Access::AccelStructBuild);
        b.setSideEffects();
        rg::RgAccelStruct tlas = buildTlas ? frame.tlas : rg::RgAccelStruct{};
        // Runs when the graph executes: host writes made before the submit are visible to the GPU
        // (Vulkan spec 7.9), and the slot is not in use by an unfinished frame (frames-in-flight contract).
        return [s, data, tlas](rg::PassContext& ctx) {
            auto write = [](const rhi::BufferHandle& buffer, const std::vector<uint8_t>& bytes, std::vector<uint8_t>& written) {
                if (bytes == written) return;
                std::memcpy(buffer->mappedData(), bytes.data(), bytes.size());
                written = bytes;
            };
            write(s->tables.materials, data->materials, s->writtenMaterials);
            write(s->tables.instances, data->instances, s->writtenInstances);
            write(s->tables.lights, data->lights, s->writtenLights);
            if (!tlas.valid() || data->tlas == s->writtenTlas) return;
            std::vector<rhi::InstanceDesc> instances(data->instanceCount);
            std::memcpy(instances.data(), data->tlas.data(), data->tlas.size());
            ctx.cmd().buildTopLevel(ctx.accelStruct(tlas), instances);
            s->writtenTlas = data->tlas;
        };
    });
    return frame;
}

void LiveScene::appendMemory(std::vector<MemoryEntry>& out) const {
    for (size_t i = 0; i < slots_.size(); ++i) {
        if (!slots_[i]) continue;
        const std::string prefix = "scene.slot" + std::to_string(i) + ".";
        const SceneTables& t = slots_[i]->tables;
        addMemoryEntry(out, prefix + "tlas", t.tlas);
        addMemoryEntry(out, prefix + "materials", t.materials);
        addMemoryEntry(out, prefix + "instances", t.instances);
        addMemoryEntry(out, prefix + "lights", t.lights);
    }
}

}  // namespace caustics
