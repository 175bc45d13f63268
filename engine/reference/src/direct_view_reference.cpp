#include "caustics/reference/direct_view_reference.h"

#include <algorithm>
#include <cmath>
#include <thread>

#include "common/bsdf.h"
#include "common/camera.h"
#include "common/emission.h"
#include "common/view_lobes.h"
#include "world.h"

namespace caustics::reference {
namespace sh = caustics::shader;
namespace {

struct ViewContext {
    const scene::Scene& scene;
    const WorldScene& world;
    DirectViewOptions options;
};

// Direction to the light, distance and irradiance on a surface facing it (KHR_lights_punctual:
// E = I / d^2 with the recommended range window, smooth spot cone; directional E = lux).
struct LightArrival {
    glm::vec3 toLight;
    float distance;
    glm::vec3 irradiance;
};

LightArrival arrival(const scene::Light& light, const glm::vec3& p) {
    glm::vec3 color = light.color * light.intensity;
    if (light.type == scene::LightType::Directional) return {-glm::normalize(light.direction), 1.0e6f, color};
    glm::vec3 v = light.position - p;
    float d = std::max(glm::length(v), 1e-4f);
    float falloff = 1.0f / (d * d);
    if (light.range > 0.0f) {
        float r = d / light.range;
        float w = std::clamp(1.0f - r * r * r * r, 0.0f, 1.0f);
        falloff *= w * w;
    }
    glm::vec3 toLight = v / d;
    if (light.type == scene::LightType::Spot)
        falloff *= sh::spotAttenuation(glm::dot(-toLight, glm::normalize(light.direction)), std::cos(light.innerConeAngle),
                                       std::cos(light.outerConeAngle));
    return {toLight, d, color * falloff};
}

// Sum over lights of f_r E cos V at a surface point (n faces the viewer, v towards the viewer); diffuseOnly:
// the BRDF's diffuse term alone (sh::evalGltfDiffuse).
glm::vec3 shadeDirect(const ViewContext& ctx, const glm::vec3& x, const glm::vec3& n, const glm::vec3& v,
                      const sh::BrdfMaterial& brdf, bool diffuseOnly) {
    glm::vec3 sum(0.0f);
    float eps = rayEpsilon(x);
    for (const scene::Light& light : ctx.scene.lights) {
        LightArrival a = arrival(light, x);
        float cosL = glm::dot(n, a.toLight);
        if (cosL <= 0.0f) continue;
        glm::vec3 f = diffuseOnly ? sh::evalGltfDiffuse(brdf, n, a.toLight, v) : sh::evalGltfBrdf(brdf, n, a.toLight, v);
        if (sh::maxComponent(f) <= 0.0f) continue;
        if (ctx.world.bvh->occluded(x + n * eps, a.toLight, 0.0f, std::max(a.distance - 2.0f * eps, 0.0f))) continue;
        sum += f * a.irradiance * cosL;
    }
    return sum;
}

// Radiance arriving at `origin` from direction -dir, times `weight`; recursion depth <= maxSpecularEvents.
glm::vec3 traceView(const ViewContext& ctx, const glm::vec3& origin, const glm::vec3& dir, const glm::vec3& weight,
                    uint32_t events) {
    RayHit hit;
    if (!ctx.world.bvh->intersect(origin, dir, 0.0f, 1e30f, hit)) return glm::vec3(0.0f);
    SurfacePoint sp = surfaceAt(ctx.scene, ctx.world, origin, dir, hit);
    const glm::vec3 x = sp.position, ns = sp.shadingNormal, ng = sp.geometricNormal, albedo = sp.albedo;
    const scene::Material& mat = *sp.material;
    glm::vec3 facing = glm::dot(ns, dir) < 0.0f ? ns : -ns;
    sh::BrdfMaterial brdf = sh::makeBrdfMaterial(albedo, mat.metallic, mat.roughness, mat.transmission,
                                                 sh::gltfDielectricF0(mat.specular, mat.ior));
    // A specular surface shows its own highlight only when the camera sees it directly (as on the GPU);
    // seen through glass or in a mirror, its diffuse base's direct light alone.
    const bool highlight = !mat.isSpecular() || events == 0;
    glm::vec3 radiance = weight * shadeDirect(ctx, x, facing, -dir, brdf, !highlight);
    if (!mat.isSpecular() || events >= ctx.options.maxSpecularEvents) return radiance;

    bool entering = glm::dot(dir, ng) < 0.0f;
    sh::ViewLobes lobes = sh::specularViewLobes(dir, facing, albedo, mat.metallic, mat.transmission, mat.ior,
                                                mat.isThinWalled(), entering);
    float eps = rayEpsilon(x);
    auto follow = [&](const glm::vec3& d, const glm::vec3& w) {
        glm::vec3 branch = weight * w;
        if (sh::maxComponent(branch) < ctx.options.minBranchWeight) return glm::vec3(0.0f);
        glm::vec3 o = x + (glm::dot(d, facing) > 0.0f ? facing : -facing) * eps;
        return traceView(ctx, o, d, branch, events + 1);
    };
    radiance += follow(lobes.reflectDirection, lobes.reflectWeight);
    radiance += follow(lobes.refractDirection, lobes.refractWeight);
    return radiance;
}

}  // namespace

Result<ReferenceImage> renderDirectViewReference(const scene::Scene& scene, const scene::Camera& camera,
                                                 const DirectViewOptions& options) {
    CAUSTICS_CHECK(checkReferenceInputs("renderDirectViewReference", scene, camera, options.width, options.height));
    WorldScene world = buildWorldScene(scene);
    ViewContext ctx{scene, world, options};
    sh::PinholeCamera cam = sh::makePinholeCamera(camera.eye, camera.target, camera.up, camera.verticalFovRadians,
                                                  float(options.width), float(options.height));
    ReferenceImage out;
    out.width = options.width;
    out.height = options.height;
    out.pixels.assign(size_t(options.width) * options.height, glm::vec3(0.0f));
    uint32_t threadCount = options.threads ? options.threads : std::max(1u, std::thread::hardware_concurrency());
    auto worker = [&](uint32_t k) {
        for (uint32_t y = k; y < options.height; y += threadCount)
            for (uint32_t x = 0; x < options.width; ++x) {
                glm::vec3 d = sh::cameraRayDirection(cam, glm::vec2(float(x) + 0.5f, float(y) + 0.5f));
                out.pixels[size_t(y) * options.width + x] = traceView(ctx, camera.eye, d, glm::vec3(1.0f), 0);
            }
    };
    std::vector<std::thread> pool;
    for (uint32_t k = 1; k < threadCount; ++k) pool.emplace_back(worker, k);
    worker(0);
    for (std::thread& t : pool) t.join();
    return out;
}

}  // namespace caustics::reference
