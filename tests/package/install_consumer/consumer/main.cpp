// The package consumer (tests/package): creates a device, a built-in scene and the module, renders one
// small caustics frame and checks that the caustic image has light in it. Exit code 0 = it worked.
#include <cstdio>
#include <vector>

#include <glm/glm.hpp>

#include "caustics/caustics_module.h"
#include "caustics/rhi/rhi.h"
#include "caustics/scene/builtin_scenes.h"
#include "caustics/scene/gpu_scene.h"

int main() {
    using namespace caustics;
    rhi::DeviceDesc dd;
    dd.requireRayTracing = true;
    auto device = rhi::createDevice(dd);
    if (!device) return std::fprintf(stderr, "device: %s\n", device.message().c_str()), 1;
    scene::Scene scene = scene::makeGlassSphereScene(scene::AnalyticSceneDesc{.tessellation = 24});
    auto gpuScene = scene::GpuScene::create(*device.value(), scene);
    if (!gpuScene) return std::fprintf(stderr, "scene: %s\n", gpuScene.message().c_str()), 1;
    CausticsSettings s;
    s.mapResolution = 32;
    s.filter = false;
    s.maxStoredHits = 1u << 12;
    auto module = CausticsModule::create(device.value(), scene, gpuScene.value(), s);
    if (!module) return std::fprintf(stderr, "module: %s\n", module.message().c_str()), 1;
    constexpr uint32_t kSize = 32;
    scene::Camera cam;
    cam.eye = {0.0f, 2.5f, 1.5f};
    cam.target = {0.0f, 0.0f, 0.0f};
    rg::RenderGraph graph;
    FrameInputs in;
    in.camera = cameraViewMatrices(cam, kSize, kSize);
    in.width = in.height = kSize;
    auto out = module.value()->addPasses(graph, in);
    if (!out) return std::fprintf(stderr, "addPasses: %s\n", out.message().c_str()), 1;
    graph.markOutput(out->caustics, rhi::ResourceState::CopySource);
    auto readback = device.value()->createBuffer(rhi::BufferDesc().setByteSize(kSize * kSize * 16)
                                                     .setUsage(rhi::BufferUsage::CopyDest)
                                                     .setMemory(rhi::MemoryType::Readback));
    auto cmd = device.value()->createCommandList();
    if (!readback || !cmd) return std::fprintf(stderr, "readback or command list creation failed\n"), 1;
    cmd.value()->begin();
    if (auto st = graph.execute(*device.value(), *cmd.value()); !st) return std::fprintf(stderr, "execute: %s\n", st.message().c_str()), 1;
    cmd.value()->copyTextureToBuffer(readback.value(), 0, graph.texture(out->caustics));
    cmd.value()->end();
    auto fence = device.value()->submit(cmd.value());
    if (!fence || !device.value()->waitForFence(fence.value())) return std::fprintf(stderr, "submit failed\n"), 1;
    std::vector<glm::vec4> pixels(kSize * kSize);
    if (!device.value()->readBuffer(readback.value(), pixels.data(), pixels.size() * 16)) return 1;
    float sum = 0.0f;
    for (const glm::vec4& p : pixels) sum += p.x + p.y + p.z;
    std::printf("caustic radiance sum over %ux%u pixels: %g\n", kSize, kSize, sum);
    return sum > 0.0f ? 0 : 1;
}
