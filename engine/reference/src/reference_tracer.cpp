#include "caustics/reference/reference_tracer.h"

#include <algorithm>
#include <cmath>
#include <string>
#include <thread>

#include "common/bsdf.h"
#include "common/camera.h"
#include "common/emission.h"
#include "common/rng.h"
#include "common/sampling.h"
#include "common/specular_event.h"
#include "common/volume.h"
#include "emission_plan.h"
#include "world.h"

namespace caustics::reference {
namespace sh = caustics::shader;
namespace {

constexpr uint64_t kChunk = 4096;  // photons per work item; items go round-robin to threads

struct Photon {
    glm::vec3 origin;
    glm::vec3 direction;
    glm::vec3 flux;  // lm per channel
};

struct Context {
    const scene::Scene& scene;
    const WorldScene& world;
    sh::PinholeCamera camera;
    float nearPlane;
    ReferenceOptions options;
};

sh::OpticalMaterial opticalMaterial(const scene::Material& m) {
    sh::OpticalMaterial o;
    o.baseColor = m.baseColor;
    o.metallic = m.metallic;
    o.roughness = m.roughness;
    o.transmission = m.transmission;
    o.ior = m.ior;
    o.thinWalled = m.isThinWalled();
    return o;
}

// Photon for texel `texel` of map `map`: the shared emission normalisation, with the direction
// jittered inside the texel (docs/physics.md: the weight uses the exact texel solid angle).
Photon emitPhoton(const scene::Light& light, const EmissionMap& map, uint32_t texel, sh::Rng& rng) {
    uint32_t tx = texel % map.size, ty = texel / map.size;
    glm::vec2 jitter = sh::rngNextFloat2(rng);
    glm::vec2 coord = glm::vec2(float(tx), float(ty)) + jitter;
    Photon p;
    glm::vec3 color = light.color;
    if (map.orthographic) {
        glm::vec2 q = map.halfExtent * (2.0f * coord / float(map.size) - 1.0f);
        p.origin = map.origin + q.x * map.right + q.y * map.up;
        p.direction = map.forward;
        float area = sh::orthographicTexelArea(map.halfExtent, float(map.size));
        p.flux = color * sh::photonFluxOrthographic(light.intensity, area, 1.0f);
        return p;
    }
    glm::vec2 q = sh::perspectiveMapPlanePoint(coord, float(map.size), map.tanHalfAngle);
    p.origin = light.position;
    p.direction = glm::normalize(map.forward + q.x * map.right + q.y * map.up);
    float omega = sh::perspectiveTexelSolidAngle(sh::uint2(tx, ty), float(map.size), map.tanHalfAngle);
    float falloff = 1.0f;
    if (light.type == scene::LightType::Spot) {
        float cosTheta = glm::dot(p.direction, glm::normalize(light.direction));
        falloff = sh::spotAttenuation(cosTheta, std::cos(light.innerConeAngle), std::cos(light.outerConeAngle));
    }
    p.flux = color * falloff * sh::photonFluxPerspective(light.intensity, omega, 1.0f);
    return p;
}

// The receiver's BRDF (shaders/common/bsdf.h), as the GPU forward trace builds it: a specular
// material reaches a diffuse vertex only through its diffuse layer, already weighted by the event.
sh::BrdfMaterial receiverBrdfMaterial(const scene::Material& m, const glm::vec3& albedo) {
    if (m.isSpecular()) return sh::lambertOnlyBrdfMaterial(albedo);
    return sh::makeBrdfMaterial(albedo, m.metallic, m.roughness, m.transmission, sh::gltfDielectricF0(m.specular, m.ior));
}

// Light-tracing estimator (shaders/common/camera.h) with a ray-cast visibility test. incoming: unit,
// back along the photon's last segment (the BRDF's wi).
bool splat(const Context& ctx, const glm::vec3& x, const glm::vec3& nFacing, const glm::vec3& flux,
           const glm::vec3& incoming, const sh::BrdfMaterial& brdf, std::vector<glm::vec3>& image) {
    sh::CameraProjection proj = sh::projectToCamera(ctx.camera, x);
    if (!proj.valid || proj.depth < ctx.nearPlane) return false;
    glm::vec3 toEye = (ctx.camera.eye - x) / proj.distance;
    float cosSurface = glm::dot(nFacing, toEye);
    if (cosSurface <= 0.0f) return false;
    if (ctx.options.visibilityTest) {
        float eps = rayEpsilon(x);
        if (ctx.world.bvh->occluded(x + nFacing * eps, toEye, 0.0f, proj.distance * (1.0f - 1e-5f))) return false;
    }
    float factor = sh::pinholeSplatFactor(ctx.camera, proj.cosTheta, cosSurface, proj.distance);
    uint32_t px = std::min(uint32_t(proj.pixel.x), ctx.options.width - 1);
    uint32_t py = std::min(uint32_t(proj.pixel.y), ctx.options.height - 1);
    image[size_t(py) * ctx.options.width + px] += flux * sh::evalGltfBrdf(brdf, nFacing, incoming, toEye) * factor;
    return true;
}

uint64_t tracePhoton(const Context& ctx, Photon p, sh::Rng& rng, std::vector<glm::vec3>& image) {
    const ReferenceOptions& o = ctx.options;
    uint32_t specularEvents = 0, diffuseBounces = 0, vertices = 0;
    glm::vec3 sigma(0.0f);  // absorption of the medium the photon travels in
    glm::vec3 throughput(1.0f);
    uint64_t splats = 0;
    while (vertices++ < 4 * (o.maxDepth + 1)) {
        RayHit hit;
        if (!ctx.world.bvh->intersect(p.origin, p.direction, 0.0f, 1e30f, hit)) break;
        if (sigma != glm::vec3(0.0f)) p.flux *= sh::beerLambert(sigma, hit.t);
        SurfacePoint sp = surfaceAt(ctx.scene, ctx.world, p.origin, p.direction, hit);
        const glm::vec3 x = sp.position, ns = sp.shadingNormal, ng = sp.geometricNormal, albedo = sp.albedo;
        const scene::Material& mat = *sp.material;
        float eps = rayEpsilon(x);

        if (mat.isSpecular()) {
            if (specularEvents >= o.maxDepth) break;
            sh::SpecularEvent ev = sh::sampleSpecularEvent(p.direction, ns, opticalMaterial(mat),
                                                           sh::rngNextFloat3(rng), sh::kTransportImportance);
            if (ev.kind == sh::kEventAbsorbed) break;
            if (ev.kind != sh::kEventDiffuse) {
                ++specularEvents;
                p.flux *= ev.weight;
                p.direction = ev.direction;
                sigma = ev.insideMedium ? sh::volumeSigmaA(mat.attenuationColor, mat.attenuationDistance) : glm::vec3(0.0f);
                p.origin = x + (glm::dot(p.direction, ng) > 0.0f ? ng : -ng) * eps;
                throughput *= ev.weight;
                if (o.russianRoulette && specularEvents >= 2) {
                    // Survival proportional to the path throughput; survivors are reweighted (unbiased).
                    float survive = std::min(1.0f, std::max({throughput.x, throughput.y, throughput.z}));
                    if (sh::rngNextFloat(rng) >= survive) break;
                    p.flux /= survive;
                    throughput /= survive;
                }
                continue;
            }
            // The diffuse base layer of a partly transmissive/metallic material: a diffuse vertex.
        }
        glm::vec3 nFacing = glm::dot(ns, p.direction) < 0.0f ? ns : -ns;
        sh::BrdfMaterial brdf = receiverBrdfMaterial(mat, albedo);
        glm::vec3 incoming = -p.direction;
        if (o.mode == ReferenceMode::AllLightPaths || specularEvents > 0) {
            splats += splat(ctx, x, nFacing, p.flux, incoming, brdf, image) ? 1 : 0;
        }
        if (o.mode == ReferenceMode::CausticsOnly || diffuseBounces >= o.maxDepth) break;
        // Bounce by cosine sampling: the weight f cos / pdf = pi f (= albedo for pure Lambert).
        // f(wi, wo) with wi the photon's arrival and wo the new direction (the BRDF is reciprocal).
        ++diffuseBounces;
        p.direction = sh::onbToWorld(sh::onbFromNormal(nFacing), sh::sampleCosineHemisphere(sh::rngNextFloat2(rng)));
        p.flux *= sh::kPi * sh::evalGltfBrdf(brdf, nFacing, incoming, p.direction);
        p.origin = x + (glm::dot(p.direction, ng) > 0.0f ? ng : -ng) * eps;
        sigma = glm::vec3(0.0f);
    }
    return splats;
}

}  // namespace

Result<ReferenceImage> renderCausticsReference(const scene::Scene& scene, const scene::Camera& camera,
                                               const ReferenceOptions& options) {
    CAUSTICS_CHECK(checkReferenceInputs("renderCausticsReference", scene, camera, options.width, options.height));

    WorldScene world = buildWorldScene(scene);
    Context ctx{scene, world,
                sh::makePinholeCamera(camera.eye, camera.target, camera.up, camera.verticalFovRadians,
                                      float(options.width), float(options.height)),
                camera.nearPlane, options};

    struct Job {
        uint32_t light;
        uint32_t map;
        uint64_t firstTexel;
        uint64_t count;
    };
    std::vector<Job> jobs;
    std::vector<EmissionPlan> plans;
    bool fit = options.mode == ReferenceMode::CausticsOnly;
    uint64_t emitted = 0;
    for (uint32_t l = 0; l < scene.lights.size(); ++l) {
        plans.push_back(planEmission(scene.lights[l], world, options.photonsPerLight, fit));
        for (uint32_t m = 0; m < plans.back().maps.size(); ++m) {
            uint64_t texels = uint64_t(plans.back().maps[m].size) * plans.back().maps[m].size;
            for (uint64_t t = 0; t < texels; t += kChunk) jobs.push_back({l, m, t, std::min(kChunk, texels - t)});
            emitted += texels;
        }
    }

    uint32_t threadCount = options.threads ? options.threads : std::max(1u, std::thread::hardware_concurrency());
    std::vector<std::vector<glm::vec3>> images(threadCount);
    std::vector<uint64_t> splatCounts(threadCount, 0);
    auto worker = [&](uint32_t k) {
        images[k].assign(size_t(options.width) * options.height, glm::vec3(0.0f));
        for (size_t j = k; j < jobs.size(); j += threadCount) {
            const Job& job = jobs[j];
            const scene::Light& light = scene.lights[job.light];
            const EmissionMap& map = plans[job.light].maps[job.map];
            for (uint64_t t = job.firstTexel; t < job.firstTexel + job.count; ++t) {
                // One RNG stream per (texel, light, map, seed): independent of the thread split.
                sh::Rng rng = sh::rngCreate(uint32_t(t), job.light, job.map, options.seed);
                Photon p = emitPhoton(light, map, uint32_t(t), rng);
                if (p.flux == glm::vec3(0.0f)) continue;
                splatCounts[k] += tracePhoton(ctx, p, rng, images[k]);
            }
        }
    };
    std::vector<std::thread> pool;
    for (uint32_t k = 1; k < threadCount; ++k) pool.emplace_back(worker, k);
    worker(0);
    for (std::thread& t : pool) t.join();

    ReferenceImage out;
    out.width = options.width;
    out.height = options.height;
    out.pixels.assign(size_t(options.width) * options.height, glm::vec3(0.0f));
    out.photonsEmitted = emitted;
    for (uint32_t k = 0; k < threadCount; ++k) {
        for (size_t i = 0; i < out.pixels.size(); ++i) out.pixels[i] += images[k][i];
        out.photonsSplatted += splatCounts[k];
    }
    return out;
}

}  // namespace caustics::reference
