#include "caustics/reference/second_type_reference.h"

#include <algorithm>
#include <cmath>
#include <string>
#include <thread>

#include "common/camera.h"
#include "common/rng.h"
#include "common/specular_event.h"
#include "common/volume.h"
#include "world.h"

namespace caustics::reference {
namespace sh = caustics::shader;
namespace {

float rayEpsilon(const glm::vec3& p) { return 1e-4f * (1.0f + std::max({std::abs(p.x), std::abs(p.y), std::abs(p.z)})); }

sh::OpticalMaterial opticalMaterial(const scene::Material& m) {
    return sh::OpticalMaterial{m.baseColor, m.metallic, m.roughness, m.transmission, m.ior, m.isThinWalled()};
}

// Bilinear read of the receiver histogram at world point p (bin centres at (i + 0.5) / N).
glm::vec3 readHistogram(const ReferenceImage& h, const SecondTypeReferenceOptions& o, const glm::vec3& p) {
    float fx = (0.5f + 0.5f * (p.x - o.receiverCentre.x) / o.receiverHalfSize) * float(h.width) - 0.5f;
    float fy = (0.5f + 0.5f * (p.z - o.receiverCentre.y) / o.receiverHalfSize) * float(h.height) - 0.5f;
    float x0 = std::floor(fx), y0 = std::floor(fy);
    glm::vec3 sum(0.0f);
    for (int dy = 0; dy < 2; ++dy)
        for (int dx = 0; dx < 2; ++dx) {
            int x = int(x0) + dx, y = int(y0) + dy;
            if (x < 0 || y < 0 || x >= int(h.width) || y >= int(h.height)) continue;
            float w = (dx ? fx - x0 : 1.0f - (fx - x0)) * (dy ? fy - y0 : 1.0f - (fy - y0));
            sum += w * h.at(uint32_t(x), uint32_t(y));
        }
    return sum;
}

struct PathContext {
    const scene::Scene& scene;
    const WorldScene& world;
    const ReferenceImage& histogram;
    const SecondTypeReferenceOptions& options;
    sh::PinholeCamera camera;
    float nearPlane;
};

// One camera path through continuous pixel position `pixel` (radiance transport, Fresnel lobes picked
// with their probabilities as on the GPU): the radiance it carries back from the receiver plane, or
// zero when it does not reach the plane after at least one specular event.
glm::vec3 traceCameraPath(const PathContext& ctx, glm::vec2 pixel, sh::Rng& rng, bool& onReceiver) {
    const SecondTypeReferenceOptions& o = ctx.options;
    glm::vec3 origin = ctx.camera.eye, dir = sh::cameraRayDirection(ctx.camera, pixel);
    glm::vec3 throughput(1.0f), sigma(0.0f);
    uint32_t events = 0;
    onReceiver = false;
    for (uint32_t vertex = 0; vertex <= o.maxDepth + 1; ++vertex) {
        RayHit hit;
        if (!ctx.world.bvh->intersect(origin, dir, vertex == 0 ? ctx.nearPlane : 0.0f, 1e30f, hit)) return glm::vec3(0.0f);
        if (sigma != glm::vec3(0.0f)) throughput *= sh::beerLambert(sigma, hit.t);
        const Triangle& tri = ctx.world.triangles[hit.triangle];
        glm::vec3 x = origin + hit.t * dir;
        glm::vec3 ng = glm::normalize(glm::cross(tri.p1 - tri.p0, tri.p2 - tri.p0));
        const glm::vec3* vn = &ctx.world.normals[size_t(hit.triangle) * 3];
        glm::vec3 ns = glm::normalize((1.0f - hit.u - hit.v) * vn[0] + hit.u * vn[1] + hit.v * vn[2]);
        if (glm::dot(ns, ng) < 0.0f) ng = -ng;
        const scene::Material& mat = ctx.scene.materials[ctx.world.materials[hit.triangle]];
        if (mat.isSpecular()) {
            if (events >= o.maxDepth) return glm::vec3(0.0f);
            sh::SpecularEvent ev = sh::sampleSpecularEvent(dir, ns, opticalMaterial(mat), sh::rngNextFloat3(rng), sh::kTransportRadiance);
            if (ev.kind == sh::kEventAbsorbed || ev.kind == sh::kEventDiffuse) return glm::vec3(0.0f);
            ++events;
            throughput *= ev.weight;
            dir = ev.direction;
            sigma = ev.insideMedium ? sh::volumeSigmaA(mat.attenuationColor, mat.attenuationDistance) : glm::vec3(0.0f);
            origin = x + (glm::dot(dir, ng) > 0.0f ? ng : -ng) * rayEpsilon(x);
            continue;
        }
        // The receiver: the plane's upper side, reached from above, inside the binned square.
        bool onPlane = std::abs(x.y - o.receiverHeight) < 10.0f * rayEpsilon(x) && ns.y > 0.999f && dir.y < 0.0f &&
                       std::abs(x.x - o.receiverCentre.x) <= o.receiverHalfSize &&
                       std::abs(x.z - o.receiverCentre.y) <= o.receiverHalfSize;
        if (events == 0 || !onPlane) return glm::vec3(0.0f);
        onReceiver = true;
        return throughput * readHistogram(ctx.histogram, o, x);
    }
    return glm::vec3(0.0f);
}

}  // namespace

Result<SecondTypeReference> renderSecondTypeReference(const scene::Scene& scene, const scene::Camera& camera,
                                                      const SecondTypeReferenceOptions& options) {
    const char* fn = "renderSecondTypeReference: ";
    if (options.width == 0 || options.height == 0) return makeError(std::string(fn) + "image size is zero");
    if (options.samplesPerPixel == 0) return makeError(std::string(fn) + "samplesPerPixel is zero");
    if (!(options.receiverHalfSize > 0.0f) || options.histogramResolution == 0)
        return makeError(std::string(fn) + "receiverHalfSize and histogramResolution must be positive");

    // The histogram: the receiver seen straight down from 10 half-sizes above, the square filling the
    // image. A plane parallel to the image plane maps to it by a uniform scale, so each image pixel is
    // one square bin, and the light-tracing splat (docs/physics.md) gives the bin's mean radiance.
    SecondTypeReference out;
    scene::Camera top;
    top.eye = glm::vec3(options.receiverCentre.x, options.receiverHeight + 10.0f * options.receiverHalfSize, options.receiverCentre.y);
    top.target = glm::vec3(options.receiverCentre.x, options.receiverHeight, options.receiverCentre.y);
    top.up = glm::vec3(0.0f, 0.0f, -1.0f);
    top.verticalFovRadians = 2.0f * std::atan(0.1f);
    top.nearPlane = 1e-3f * options.receiverHalfSize;
    top.farPlane = 1e3f * options.receiverHalfSize;
    ReferenceOptions ho;
    ho.width = ho.height = options.histogramResolution;
    ho.photonsPerLight = options.photonsPerLight;
    ho.maxDepth = options.maxDepth;
    ho.seed = options.seed;
    ho.threads = options.threads;
    ho.visibilityTest = false;  // the specular objects above the plane must not hide it
    CAUSTICS_TRY(out.histogram, renderCausticsReference(scene, top, ho));

    WorldScene world = buildWorldScene(scene);
    PathContext ctx{scene, world, out.histogram, options,
                    sh::makePinholeCamera(camera.eye, camera.target, camera.up, camera.verticalFovRadians, float(options.width),
                                          float(options.height)),
                    camera.nearPlane};
    out.image.width = options.width;
    out.image.height = options.height;
    out.image.pixels.assign(size_t(options.width) * options.height, glm::vec3(0.0f));
    uint32_t threadCount = options.threads ? options.threads : std::max(1u, std::thread::hardware_concurrency());
    std::vector<uint64_t> onReceiver(threadCount, 0);
    auto worker = [&](uint32_t k) {
        for (uint32_t y = k; y < options.height; y += threadCount)
            for (uint32_t x = 0; x < options.width; ++x) {
                sh::Rng rng = sh::rngCreate(y * options.width + x, 0x2ec0u, 2u, options.seed);
                glm::vec3 sum(0.0f);
                for (uint32_t s = 0; s < options.samplesPerPixel; ++s) {
                    glm::vec2 pixel = glm::vec2(float(x), float(y)) + sh::rngNextFloat2(rng);
                    bool hit = false;
                    sum += traceCameraPath(ctx, pixel, rng, hit);
                    onReceiver[k] += hit ? 1 : 0;
                }
                out.image.pixels[size_t(y) * options.width + x] = sum / float(options.samplesPerPixel);
            }
    };
    std::vector<std::thread> pool;
    for (uint32_t k = 1; k < threadCount; ++k) pool.emplace_back(worker, k);
    worker(0);
    for (std::thread& t : pool) t.join();
    for (uint64_t n : onReceiver) out.pathsOnReceiver += n;
    return out;
}

}  // namespace caustics::reference
