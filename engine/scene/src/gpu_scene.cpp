#include "caustics/scene/gpu_scene.h"

#include "caustics/scene/mesh_utils.h"
#include "caustics/scene/procedural_textures.h"

namespace caustics::scene {

GpuMaterial toGpuMaterial(const Material& m) {
    GpuMaterial g;
    g.baseColor = m.baseColor;
    g.metallic = m.metallic;
    g.specularColor = m.specularColor;
    g.roughness = m.roughness;
    g.attenuationColor = m.attenuationColor;
    g.attenuationDistance = m.attenuationDistance;
    g.emissive = m.emissive;
    g.ior = m.ior;
    g.transmission = m.transmission;
    g.specular = m.specular;
    g.thickness = m.thickness;
    g.baseColorTexture = m.baseColorTexture;
    g.flags = (m.isSpecular() ? kMaterialSpecular : 0u) | (m.transmission > 0.0f ? kMaterialTransmissive : 0u) |
              (m.metallic > 0.5f ? kMaterialMetallic : 0u) | (m.doubleSided ? kMaterialDoubleSided : 0u) |
              (m.isThinWalled() ? kMaterialThinWalled : 0u);
    return g;
}

GpuInstance toGpuInstance(const Scene& scene, const Instance& inst, uint32_t firstVertex, uint32_t firstIndex) {
    GpuInstance g;
    g.objectToWorld = inst.transform;
    g.normalToWorld = glm::mat4(normalMatrix(inst.transform));
    g.normalToWorld[3] = glm::vec4(0.0f);
    const Mesh& mesh = scene.meshes[inst.mesh];
    g.material = mesh.material;
    g.firstVertex = firstVertex;
    g.firstIndex = firstIndex;
    g.triangleCount = uint32_t(mesh.indices.size() / 3);
    g.objectId = inst.objectId;
    g.mesh = inst.mesh;
    g.flags = isSpecularInstance(scene, inst) ? kInstanceSpecular : 0u;
    return g;
}

PackedScene packScene(const Scene& scene) {
    PackedScene p;
    for (const Mesh& mesh : scene.meshes) {
        GpuMeshRange r{uint32_t(p.positions.size()), uint32_t(mesh.positions.size()), uint32_t(p.indices.size()),
                       uint32_t(mesh.indices.size())};
        p.meshRanges.push_back(r);
        p.positions.insert(p.positions.end(), mesh.positions.begin(), mesh.positions.end());
        for (size_t i = 0; i < mesh.positions.size(); ++i) {
            GpuVertex v;
            if (i < mesh.normals.size()) v.normal = mesh.normals[i];
            if (i < mesh.uvs.size()) { v.u = mesh.uvs[i].x; v.v = mesh.uvs[i].y; }
            if (i < mesh.tangents.size()) v.tangent = mesh.tangents[i];
            p.vertices.push_back(v);
        }
        p.indices.insert(p.indices.end(), mesh.indices.begin(), mesh.indices.end());
    }
    for (const Material& m : scene.materials) p.materials.push_back(toGpuMaterial(m));
    if (p.materials.empty()) p.materials.push_back(GpuMaterial{});   // never an empty storage buffer
    for (const Instance& inst : scene.instances)
        p.instances.push_back(toGpuInstance(scene, inst, p.meshRanges[inst.mesh].firstVertex, p.meshRanges[inst.mesh].firstIndex));
    return p;
}

rhi::InstanceDesc makeInstanceDesc(const Scene& scene, uint32_t index) {
    const Instance& inst = scene.instances[index];
    rhi::InstanceDesc d;
    for (int row = 0; row < 3; ++row)
        for (int col = 0; col < 4; ++col) d.transform[row][col] = inst.transform[col][row];   // glm is column-major
    d.instanceId = index;
    d.instanceMask = isSpecularInstance(scene, inst) ? kMaskSpecular : kMaskDiffuse;
    d.hitGroupOffset = 0;
    d.flags = 0;
    return d;
}

namespace {

template <typename T>
Result<rhi::BufferHandle> uploadBuffer(rhi::IDevice& device, rhi::ICommandList& cmd, const std::vector<T>& data,
                                       rhi::BufferUsage usage, uint32_t stride, const char* name) {
    rhi::BufferDesc desc;
    uint64_t bytes = std::max<uint64_t>(data.size() * sizeof(T), 16);   // never a zero-sized buffer
    desc.setByteSize(bytes).setUsage(usage | rhi::BufferUsage::CopyDest).setStructStride(stride).setDebugName(name);
    CAUSTICS_TRY(rhi::BufferHandle buffer, device.createBuffer(desc));
    cmd.barrier(rhi::BufferBarrier{buffer, rhi::ResourceState::Undefined, rhi::ResourceState::CopyDest});
    if (!data.empty()) cmd.writeBuffer(buffer, data.data(), data.size() * sizeof(T));
    return buffer;
}

}  // namespace

Result<GpuScene> GpuScene::create(rhi::IDevice& device, const Scene& sceneIn, const GpuSceneDesc& desc) {
    Scene sorted;
    const Scene* scenePtr = &sceneIn;
    if (desc.sortTriangles) {
        sorted = sceneIn;
        sortTrianglesMorton(sorted);
        scenePtr = &sorted;
    }
    const Scene& scene = *scenePtr;
    for (const Instance& inst : scene.instances)
        if (inst.mesh >= scene.meshes.size()) return makeError("GpuScene: an instance refers to a missing mesh");
    if (!desc.uploadGeometry && desc.buildAccelStructs)
        return makeError("GpuScene: buildAccelStructs needs the geometry; uploadGeometry = false is for a host that "
                         "hands in its own TLAS and geometry tables (set buildAccelStructs = false too)");
    PackedScene packed = packScene(scene);

    GpuScene out;
    out.meshRanges = packed.meshRanges;
    out.instanceCount = uint32_t(scene.instances.size());
    out.materialCount = uint32_t(packed.materials.size());
    CAUSTICS_TRY(rhi::CommandListHandle cmd, device.createCommandList());
    cmd->begin();
    using U = rhi::BufferUsage;
    if (desc.uploadGeometry) {
        CAUSTICS_TRY(out.positions, uploadBuffer(device, *cmd, packed.positions, U::Storage | U::Vertex | U::AccelStructInput, 4, "scene positions"));
        CAUSTICS_TRY(out.vertices, uploadBuffer(device, *cmd, packed.vertices, U::Storage | U::Vertex, sizeof(GpuVertex), "scene vertices"));
        CAUSTICS_TRY(out.indices, uploadBuffer(device, *cmd, packed.indices, U::Storage | U::Index | U::AccelStructInput, 4, "scene indices"));
    }
    CAUSTICS_TRY(out.materials, uploadBuffer(device, *cmd, packed.materials, U::Storage, sizeof(GpuMaterial), "scene materials"));
    std::vector<GpuInstance> instanceTable = packed.instances;
    CAUSTICS_TRY(out.instances, uploadBuffer(device, *cmd, instanceTable, U::Storage, sizeof(GpuInstance), "scene instances"));

    std::vector<Texture> white;
    const std::vector<Texture>* textures = &scene.textures;
    if (textures->empty()) {
        white.push_back(makeSolidTexture(glm::vec3(1.0f), "white"));
        textures = &white;
    }
    std::vector<rhi::TextureBarrier> toShader;
    for (const Texture& tex : *textures) {
        rhi::TextureDesc td;
        td.setSize(std::max(tex.width, 1u), std::max(tex.height, 1u)).setFormat(rhi::Format::RGBA8_SRGB).setDebugName(tex.name);
        CAUSTICS_TRY(rhi::TextureHandle handle, device.createTexture(td));
        cmd->barrier(rhi::TextureBarrier{handle, rhi::ResourceState::Undefined, rhi::ResourceState::CopyDest});
        std::vector<uint8_t> fallback;
        const std::vector<uint8_t>* pixels = &tex.rgba8;
        if (tex.rgba8.size() != size_t(td.width) * td.height * 4) {   // malformed: upload white
            fallback.assign(size_t(td.width) * td.height * 4, 255);
            pixels = &fallback;
        }
        cmd->writeTexture(handle, 0, 0, pixels->data(), pixels->size());
        toShader.push_back({handle, rhi::ResourceState::CopyDest, rhi::ResourceState::ShaderResource});
        out.textures.push_back(handle);
    }
    const rhi::ResourceState readStates = rhi::ResourceState::ShaderResource | rhi::ResourceState::AccelStructBuildInput;
    std::vector<rhi::BufferBarrier> buffers = {
        {out.positions, rhi::ResourceState::CopyDest, readStates | rhi::ResourceState::VertexBuffer},
        {out.vertices, rhi::ResourceState::CopyDest, rhi::ResourceState::ShaderResource | rhi::ResourceState::VertexBuffer},
        {out.indices, rhi::ResourceState::CopyDest, readStates | rhi::ResourceState::IndexBuffer},
        {out.materials, rhi::ResourceState::CopyDest, rhi::ResourceState::ShaderResource},
        {out.instances, rhi::ResourceState::CopyDest, rhi::ResourceState::ShaderResource},
    };
    std::erase_if(buffers, [](const rhi::BufferBarrier& b) { return !b.buffer; });   // geometry not uploaded
    cmd->barriers(toShader, buffers);

    if (desc.buildAccelStructs && !scene.instances.empty()) {
        std::vector<rhi::AccelStructBarrier> built;
        for (size_t m = 0; m < scene.meshes.size(); ++m) {
            const GpuMeshRange& r = out.meshRanges[m];
            rhi::TriangleGeometry tri;
            tri.vertexBuffer = out.positions;
            tri.vertexOffset = uint64_t(r.firstVertex) * sizeof(glm::vec3);
            tri.vertexCount = r.vertexCount;
            tri.vertexStride = sizeof(glm::vec3);
            tri.indexBuffer = out.indices;
            tri.indexOffset = uint64_t(r.firstIndex) * sizeof(uint32_t);
            tri.indexCount = r.indexCount;
            const Material* mat = scene.meshes[m].material < scene.materials.size() ? &scene.materials[scene.meshes[m].material] : nullptr;
            // Any-hit shaders that accumulate must run once per primitive (docs/caustics.md, "Second type").
            rhi::GeometryFlags flags = rhi::GeometryFlags::Opaque;
            if (mat && mat->isSpecular()) flags = flags | rhi::GeometryFlags::NoDuplicateAnyHit;
            rhi::AccelStructDesc ad;
            ad.geometries.push_back(rhi::GeometryDesc::fromTriangles(tri, flags));
            ad.flags = rhi::AccelBuildFlags::PreferFastTrace;
            ad.debugName = "BLAS " + scene.meshes[m].name;
            CAUSTICS_TRY(rhi::AccelStructHandle blas, device.createAccelStruct(ad));
            cmd->buildBottomLevel(blas);
            built.push_back({blas, rhi::ResourceState::AccelStructWrite, rhi::ResourceState::AccelStructRead});
            out.blases.push_back(blas);
        }
        cmd->barriers({}, {}, built);
        for (uint32_t i = 0; i < out.instanceCount; ++i) {
            rhi::InstanceDesc d = makeInstanceDesc(scene, i);
            d.blasAddress = out.blases[scene.instances[i].mesh]->deviceAddress();
            out.tlasInstances.push_back(d);
        }
        rhi::AccelStructDesc td;
        td.isTopLevel = true;
        td.maxInstances = out.instanceCount;
        td.debugName = "scene TLAS";
        CAUSTICS_TRY(out.tlas, device.createAccelStruct(td));
        cmd->buildTopLevel(out.tlas, out.tlasInstances);
        cmd->barrier(rhi::AccelStructBarrier{out.tlas, rhi::ResourceState::AccelStructWrite, rhi::ResourceState::AccelStructRead});
    }
    cmd->end();
    CAUSTICS_TRY(uint64_t fence, device.submit(cmd));
    CAUSTICS_CHECK(device.waitForFence(fence));
    return out;
}

}  // namespace caustics::scene
