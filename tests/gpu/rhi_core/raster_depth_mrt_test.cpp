// Two overlapping quads at different depths drawn into a colour target and an id target with a depth
// buffer: each pixel must show the nearer quad. Quad edges lie on integer pixel coordinates, so every
// pixel centre (at .5) is 0.5 px from any edge and coverage is exact; no tolerance is needed.
#include <cstring>

#include "gpu_test.h"

namespace caustics::test {
namespace {
using namespace rhi;

constexpr uint32_t kSize = 64;

struct Vertex {
    float position[3];
    uint32_t id;
};

// Axis-aligned quad in pixel units [x0, x1) x [y0, y1) at depth z.
void addQuad(std::vector<Vertex>& v, std::vector<uint32_t>& idx, float x0, float y0, float x1, float y1, float z,
             uint32_t id) {
    auto ndc = [](float p) { return p / kSize * 2.0f - 1.0f; };
    const uint32_t base = uint32_t(v.size());
    v.push_back({{ndc(x0), ndc(y0), z}, id});
    v.push_back({{ndc(x1), ndc(y0), z}, id});
    v.push_back({{ndc(x1), ndc(y1), z}, id});
    v.push_back({{ndc(x0), ndc(y1), z}, id});
    for (uint32_t i : {0u, 1u, 2u, 0u, 2u, 3u}) idx.push_back(base + i);
}

bool inside(uint32_t px, uint32_t py, float x0, float y0, float x1, float y1) {
    const float cx = px + 0.5f, cy = py + 0.5f;
    return cx >= x0 && cx < x1 && cy >= y0 && cy < y1;
}

TEST_F(GpuTest, RasterWithDepthAndTwoTargetsShowsNearerQuadPerPixel) {
    // Quad 2 (near, z=0.25) is drawn first, quad 1 (far, z=0.5) second: the depth test must reject
    // quad 1 where they overlap.
    std::vector<Vertex> vertices;
    std::vector<uint32_t> indices;
    addQuad(vertices, indices, 24, 24, 56, 56, 0.25f, 2);
    addQuad(vertices, indices, 8, 8, 40, 40, 0.5f, 1);

    auto vb = device->createBuffer(BufferDesc()
                                       .setByteSize(vertices.size() * sizeof(Vertex))
                                       .setUsage(BufferUsage::Vertex | BufferUsage::CopyDest)
                                       .setDebugName("vertices"));
    auto ib = device->createBuffer(BufferDesc()
                                       .setByteSize(indices.size() * 4)
                                       .setUsage(BufferUsage::Index | BufferUsage::CopyDest)
                                       .setDebugName("indices"));
    auto color = device->createTexture(TextureDesc()
                                           .setSize(kSize, kSize)
                                           .setFormat(Format::RGBA8_UNORM)
                                           .setUsage(TextureUsage::RenderTarget | TextureUsage::CopySource)
                                           .setDebugName("color"));
    auto ids = device->createTexture(TextureDesc()
                                         .setSize(kSize, kSize)
                                         .setFormat(Format::R32_UINT)
                                         .setUsage(TextureUsage::RenderTarget | TextureUsage::CopySource)
                                         .setDebugName("ids"));
    auto depth = device->createTexture(TextureDesc()
                                           .setSize(kSize, kSize)
                                           .setFormat(Format::D32_FLOAT)
                                           .setUsage(TextureUsage::DepthStencil)
                                           .setDebugName("depth"));
    ASSERT_TRUE(vb.ok() && ib.ok() && color.ok() && ids.ok() && depth.ok());

    GraphicsPipelineDesc pd;
    pd.vertexShader = {testShader("rhi_core/id_quad.vert"), "main", ShaderStage::Vertex};
    pd.fragmentShader = {testShader("rhi_core/id_quad.frag"), "main", ShaderStage::Fragment};
    pd.vertexBuffers = {{0, sizeof(Vertex)}};
    pd.vertexAttributes = {{0, 0, Format::RGB32_FLOAT, 0}, {1, 0, Format::R32_UINT, 12}};
    pd.colorFormats = {Format::RGBA8_UNORM, Format::R32_UINT};
    pd.depthFormat = Format::D32_FLOAT;
    pd.debugName = "id quads";
    auto pipeline = device->createGraphicsPipeline(pd);
    ASSERT_TRUE(pipeline.ok()) << pipeline.message();

    runCommands([&](ICommandList& cmd) {
        cmd.barrier(BufferBarrier{vb.value(), ResourceState::Undefined, ResourceState::CopyDest});
        cmd.barrier(BufferBarrier{ib.value(), ResourceState::Undefined, ResourceState::CopyDest});
        cmd.writeBuffer(vb.value(), vertices.data(), vertices.size() * sizeof(Vertex));
        cmd.writeBuffer(ib.value(), indices.data(), indices.size() * 4);
        cmd.barrier(BufferBarrier{vb.value(), ResourceState::CopyDest, ResourceState::VertexBuffer});
        cmd.barrier(BufferBarrier{ib.value(), ResourceState::CopyDest, ResourceState::IndexBuffer});
        const TextureBarrier toTargets[] = {
            {color.value(), ResourceState::Undefined, ResourceState::RenderTarget},
            {ids.value(), ResourceState::Undefined, ResourceState::RenderTarget},
            {depth.value(), ResourceState::Undefined, ResourceState::DepthWrite},
        };
        cmd.barriers(toTargets, {});
        RenderingDesc rd;
        rd.width = rd.height = kSize;
        rd.colors = {ColorAttachment{color.value(), 0, true, {0, 0, 0, 0}},
                     ColorAttachment{ids.value(), 0, true, {0, 0, 0, 0}}};
        rd.depth = DepthAttachment{depth.value(), 0, true, 1.0f};
        cmd.beginRendering(rd);
        cmd.setGraphicsPipeline(pipeline.value());
        cmd.setViewport(0, 0, kSize, kSize);
        cmd.setVertexBuffer(0, vb.value());
        cmd.setIndexBuffer(ib.value());
        cmd.drawIndexed(uint32_t(indices.size()));
        cmd.endRendering();
        const TextureBarrier toCopy[] = {
            {color.value(), ResourceState::RenderTarget, ResourceState::CopySource},
            {ids.value(), ResourceState::RenderTarget, ResourceState::CopySource},
        };
        cmd.barriers(toCopy, {});
    });
    std::vector<uint8_t> colorBytes = readTexture(color.value());
    std::vector<uint8_t> idBytes = readTexture(ids.value());
    ASSERT_EQ(colorBytes.size(), kSize * kSize * 4);
    ASSERT_EQ(idBytes.size(), kSize * kSize * 4);

    uint32_t wrongIds = 0, wrongColors = 0;
    for (uint32_t y = 0; y < kSize; ++y)
        for (uint32_t x = 0; x < kSize; ++x) {
            const uint32_t expectedId = inside(x, y, 24, 24, 56, 56) ? 2u : inside(x, y, 8, 8, 40, 40) ? 1u : 0u;
            const uint8_t expectedColor[4] = {uint8_t(expectedId == 1 ? 255 : 0), uint8_t(expectedId == 2 ? 255 : 0),
                                              0, uint8_t(expectedId ? 255 : 0)};
            uint32_t id;
            std::memcpy(&id, &idBytes[(y * kSize + x) * 4], 4);
            if (id != expectedId) ++wrongIds;
            if (std::memcmp(&colorBytes[(y * kSize + x) * 4], expectedColor, 4) != 0) ++wrongColors;
        }
    EXPECT_EQ(wrongIds, 0u);
    EXPECT_EQ(wrongColors, 0u);
}

}  // namespace
}  // namespace caustics::test
