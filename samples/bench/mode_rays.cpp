// `rays` mode: ray-throughput of the RHI's ray-tracing path on a procedural ~1M-triangle mesh
// (a Sponza-scale stand-in made by code, labelled as such in the output): (a) primary rays of a
// pinhole camera, (b) incoherent rays with random origins in the bounds and random directions.
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstring>

#include "bench_gpu.h"
#include "bench_modes.h"
#include "procedural_mesh.h"
#include "ray_rates.h"

namespace caustics::bench {
namespace {

using namespace caustics::rhi;

void normalize3(float* v) {
    const float len = std::sqrt(v[0] * v[0] + v[1] * v[1] + v[2] * v[2]);
    for (int i = 0; i < 3; ++i) v[i] /= len;
}

RayFrameConstants makeConstants(const BenchMesh& mesh, const BenchOptions& options) {
    RayFrameConstants c{};
    const float eye[3] = {0.0f, 0.6f, 3.2f};
    float forward[3] = {-eye[0], -eye[1], -eye[2]};
    normalize3(forward);
    float right[3] = {-forward[2], 0.0f, forward[0]};   // forward x (0, 1, 0)
    normalize3(right);
    const float up[3] = {right[1] * forward[2] - right[2] * forward[1], right[2] * forward[0] - right[0] * forward[2],
                         right[0] * forward[1] - right[1] * forward[0]};
    const float tanHalf = std::tan(0.5f * 45.0f * 3.14159265f / 180.0f);
    const float aspect = float(options.width) / float(options.height);
    for (int i = 0; i < 3; ++i) {
        c.cameraPosition[i] = eye[i];
        c.cameraForward[i] = forward[i];
        c.cameraRight[i] = right[i] * tanHalf * aspect;
        c.cameraUp[i] = up[i] * tanHalf;
        c.boundsMin[i] = mesh.boundsMin[i];
        c.boundsMax[i] = mesh.boundsMax[i];
    }
    return c;
}

int fail(const std::string& what) {
    std::fprintf(stderr, "caustics-bench rays: %s\n", what.c_str());
    return 1;
}

}  // namespace

int runRaysMode(const BenchOptions& options) {
    auto device = createBenchDevice(options);
    if (!device) return fail(device.message());
    IDevice& dev = *device.value();
    const Capabilities& caps = dev.capabilities();

    const auto cpuStart = std::chrono::steady_clock::now();
    BenchMesh mesh = makeDisplacedSphere(options.triangles);
    sortTrianglesMorton(mesh);
    const double meshSeconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - cpuStart).count();

    auto upload = [&](const void* data, uint64_t bytes, const char* name) -> BufferHandle {
        auto b = dev.createBuffer(BufferDesc().setByteSize(bytes).setUsage(BufferUsage::AccelStructInput)
                                      .setMemory(MemoryType::Upload).setDebugName(name));
        if (!b) return nullptr;
        std::memcpy(b.value()->mappedData(), data, bytes);
        return b.value();
    };
    BufferHandle vertices = upload(mesh.positions.data(), mesh.positions.size() * 4, "bench vertices");
    BufferHandle indices = upload(mesh.indices.data(), mesh.indices.size() * 4, "bench indices");
    if (!vertices || !indices) return fail("could not create the mesh buffers");

    TriangleGeometry tri{vertices, 0, uint32_t(mesh.positions.size() / 3), 12, indices, 0, uint32_t(mesh.indices.size())};
    AccelStructDesc blasDesc;
    blasDesc.geometries.push_back(GeometryDesc::fromTriangles(tri));
    blasDesc.flags = AccelBuildFlags::PreferFastTrace | AccelBuildFlags::AllowCompaction;
    blasDesc.debugName = "bench mesh";
    auto built = dev.createAccelStruct(blasDesc);
    if (!built) return fail(built.message());
    const auto buildStart = std::chrono::steady_clock::now();
    if (auto s = runOnce(dev, [&](ICommandList& cmd) { cmd.buildBottomLevel(built.value()); }); !s) return fail(s.message());
    const double buildSeconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - buildStart).count();
    auto blas = dev.compactAccelStruct(built.value());
    if (!blas) return fail(blas.message());

    AccelStructDesc tlasDesc;
    tlasDesc.isTopLevel = true;
    tlasDesc.maxInstances = 1;
    tlasDesc.debugName = "bench TLAS";
    auto tlas = dev.createAccelStruct(tlasDesc);
    if (!tlas) return fail(tlas.message());
    InstanceDesc instance;
    instance.blasAddress = blas.value()->deviceAddress();

    if (auto s = runOnce(dev, [&](ICommandList& cmd) {
            cmd.buildTopLevel(tlas.value(), std::span(&instance, 1));
            cmd.barrier(AccelStructBarrier{tlas.value(), ResourceState::AccelStructWrite, ResourceState::AccelStructRead});
        });
        !s)
        return fail(s.message());

    auto results = measureRayRates(dev, tlas.value(), makeConstants(mesh, options), options.width, options.height,
                                   options, {"primary", "incoherent"});
    if (!results) return fail(results.message());
    const uint64_t rays = uint64_t(options.width) * options.height;

    std::printf("caustics-bench rays\n");
    std::printf("device   : %s (%s, %s backend)\n", caps.adapterName.c_str(), caps.driverName.c_str(),
                backendName(options.backend));
    std::printf("scene    : procedural displaced sphere (Sponza-scale stand-in made by code), %u triangles, "
                "Morton-sorted (CPU %.2f s)\n", mesh.triangleCount(), meshSeconds);
    std::printf("BLAS     : %.1f MiB built, %.1f MiB compacted (build + wait %.2f s)\n",
                double(built.value()->storageBytes()) / (1 << 20), double(blas.value()->storageBytes()) / (1 << 20),
                buildSeconds);
    std::printf("frames   : %ux%u = %llu rays per frame, median of %u frames (after %u warm-up), GPU timestamps\n\n",
                options.width, options.height, (unsigned long long)rays, options.frames, options.warmupFrames);
    std::printf("%-12s %12s %12s %8s\n", "rays", "median ms", "Mrays/s", "hit %");
    for (const RayRate& r : results.value())
        std::printf("%-12s %12.3f %12.2f %8.1f\n", r.rayGen.c_str(), r.medianMs, r.megaRaysPerSecond(),
                    100.0 * r.hitFraction);
    return 0;
}

}  // namespace caustics::bench
