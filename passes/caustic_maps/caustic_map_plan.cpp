#include "caustics/caustic_map_plan.h"
#include "caustics/specular_clusters.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include <glm/gtc/matrix_transform.hpp>

namespace caustics {
namespace {

glm::vec4 sphereOf(glm::vec3 lo, glm::vec3 hi) { return {0.5f * (lo + hi), 0.5f * glm::length(hi - lo)}; }

void setFrame(CausticMapGpu& m, glm::vec3 forward) {
    m.forward = glm::normalize(forward);
    glm::vec3 hint = std::abs(m.forward.y) < 0.9f ? glm::vec3(0, 1, 0) : glm::vec3(1, 0, 0);
    m.right = glm::normalize(glm::cross(m.forward, hint));
    m.up = glm::cross(m.right, m.forward);
}

// World -> Vulkan clip for a map: texel (i, j) of the map covers the plane points
// extent * (2 (i, j) / N - 1) along (right, up), matching shaders/common/emission.h; clip y = +up,
// so map row j grows with `up` (the shaders use the same convention when they read the map).
glm::mat4 mapViewProj(const CausticMapGpu& m, float farPlane) {
    glm::mat4 view(1.0f);   // rows: right, up, forward (camera looks along +z here)
    for (int c = 0; c < 3; ++c) {
        view[c][0] = m.right[c];
        view[c][1] = m.up[c];
        view[c][2] = m.forward[c];
    }
    view[3] = glm::vec4(-glm::dot(m.right, m.origin), -glm::dot(m.up, m.origin), -glm::dot(m.forward, m.origin), 1);
    glm::mat4 proj(0.0f);
    float n = m.nearPlane, f = farPlane;
    if (m.orthographic) {
        proj[0][0] = 1.0f / m.extent;
        proj[1][1] = 1.0f / m.extent;
        proj[2][2] = 1.0f / (f - n);
        proj[3][2] = -n / (f - n);
        proj[3][3] = 1.0f;
    } else {
        proj[0][0] = 1.0f / m.extent;
        proj[1][1] = 1.0f / m.extent;
        proj[2][2] = f / (f - n);
        proj[3][2] = -f * n / (f - n);
        proj[2][3] = 1.0f;
    }
    return proj * view;
}

// Does the cone (apex, unit axis, half-angle) touch the sphere s?
bool coneTouchesSphere(glm::vec3 apex, glm::vec3 axis, float halfAngle, glm::vec4 s) {
    glm::vec3 v = glm::vec3(s) - apex;
    float d = glm::length(v);
    if (d <= s.w) return true;
    float angle = std::acos(std::clamp(glm::dot(v / d, axis), -1.0f, 1.0f));
    return angle <= halfAngle + std::asin(std::min(1.0f, s.w / d));
}

// The instances map m must rasterise: the specular objects inside its frustum, and the occluders there
// when asked (CausticsSettings::mapOccluders).
std::vector<uint32_t> instancesInFrustum(const CausticMapGpu& m, const SpecularBounds& bounds, bool occluders) {
    std::vector<uint32_t> drawn;
    for (uint32_t i = 0; i < bounds.allInstanceSpheres.size(); ++i) {
        glm::vec4 s = bounds.allInstanceSpheres[i];
        if (!occluders && !bounds.instanceIsSpecular[i]) continue;
        if (s.w >= 0.0f && mapFrustumTouchesSphere(m, s)) drawn.push_back(i);
    }
    return drawn;
}

}  // namespace

bool mapFrustumTouchesSphere(const CausticMapGpu& m, glm::vec4 sphere) {
    glm::vec3 v = glm::vec3(sphere) - m.origin;
    float along = glm::dot(v, m.forward);
    if (m.orthographic) {
        // The square of half-side `extent` lies inside the circle of radius extent * sqrt(2).
        float lateral = glm::length(v - along * m.forward);
        return along >= -sphere.w && lateral <= m.extent * std::sqrt(2.0f) + sphere.w;
    }
    // The square frustum's corners are at tan(half-angle) * sqrt(2) off the axis on the plane z = 1.
    float halfAngle = std::atan(m.extent * std::sqrt(2.0f));
    return coneTouchesSphere(m.origin, m.forward, halfAngle, sphere);
}

SpecularBounds computeSpecularBounds(const scene::Scene& scene) {
    SpecularBounds b;
    glm::vec3 specLo(1e30f), specHi(-1e30f), allLo(1e30f), allHi(-1e30f);
    for (const scene::Instance& inst : scene.instances) {
        if (inst.mesh >= scene.meshes.size()) {
            b.allInstanceSpheres.push_back(glm::vec4(0, 0, 0, -1));
            b.instanceIsSpecular.push_back(false);
            continue;
        }
        const scene::Mesh& mesh = scene.meshes[inst.mesh];
        const bool specular = mesh.material < scene.materials.size() && scene.materials[mesh.material].isSpecular();
        b.instanceIsSpecular.push_back(specular);
        glm::vec3 lo(1e30f), hi(-1e30f);
        for (const glm::vec3& p : mesh.positions) {
            glm::vec3 w = glm::vec3(inst.transform * glm::vec4(p, 1.0f));
            lo = glm::min(lo, w);
            hi = glm::max(hi, w);
        }
        b.allInstanceSpheres.push_back(lo.x > hi.x ? glm::vec4(0, 0, 0, -1) : sphereOf(lo, hi));
        if (lo.x > hi.x) continue;
        allLo = glm::min(allLo, lo);
        allHi = glm::max(allHi, hi);
        if (!specular) continue;
        specLo = glm::min(specLo, lo);
        specHi = glm::max(specHi, hi);
        b.instanceSpheres.push_back(sphereOf(lo, hi));
        b.specularInstances.push_back(uint32_t(&inst - scene.instances.data()));
        b.instanceLo.push_back(lo);
        b.instanceHi.push_back(hi);
    }
    if (allLo.x <= allHi.x) {
        glm::vec4 s = sphereOf(allLo, allHi);
        b.sceneCentre = glm::vec3(s);
        b.sceneRadius = s.w;
    }
    if (!b.instanceSpheres.empty()) {
        glm::vec4 s = sphereOf(specLo, specHi);
        b.centre = glm::vec3(s);
        b.radius = std::max(s.w, 1e-4f);
    }
    return b;
}

namespace {

// A light's layer before its frustum is fitted: the cluster (or clusters merged to respect
// kMaxCausticLayers) and the view coverage of its receivers.
struct LayerGroup {
    SpecularCluster cluster;
    float coverage = 1.0f;
};

// Does the light reach the cluster: some member inside the spot cone and within the range?
bool lightReaches(const scene::Light& light, const SpecularCluster& c, const SpecularBounds& bounds,
                  const std::vector<int32_t>& sphereOfInstance) {
    if (light.type == scene::LightType::Directional) return true;
    const glm::vec3 dir = glm::normalize(light.direction);
    for (uint32_t inst : c.instances) {
        const glm::vec4 s = bounds.instanceSpheres[size_t(sphereOfInstance[inst])];
        if (light.range > 0.0f && glm::length(glm::vec3(s) - light.position) - s.w >= light.range) continue;
        if (light.type == scene::LightType::Spot && !coneTouchesSphere(light.position, dir, light.outerConeAngle, s))
            continue;
        return true;
    }
    return false;
}

float groupCoverage(const SpecularCluster& c, const CausticPlanOptions& o) {
    return o.view ? viewCoverage(*o.view, causticReceiverSphere(c.sphere, o.receiverReach)) : 1.0f;
}

// Merges the two layers of the light with the most layers that fit together best, until the plan has
// at most kMaxCausticLayers (a merged layer spends more texels per object: coarser, never biased).
uint32_t capLayers(std::vector<std::vector<LayerGroup>>& perLight, const CausticPlanOptions& o) {
    uint32_t merges = 0;
    auto total = [&] {
        size_t n = 0;
        for (const auto& groups : perLight) n += groups.size();
        return n;
    };
    while (total() > kMaxCausticLayers) {
        auto& groups = *std::max_element(perLight.begin(), perLight.end(),
                                         [](const auto& a, const auto& b) { return a.size() < b.size(); });
        size_t bestA = 0, bestB = 1;
        float bestWaste = std::numeric_limits<float>::max();
        for (size_t a = 0; a < groups.size(); ++a)
            for (size_t b = a + 1; b < groups.size(); ++b) {
                const float r = enclosingSphere(groups[a].cluster.sphere, groups[b].cluster.sphere).w;
                const float waste = r * r / std::max(groups[a].cluster.memberArea + groups[b].cluster.memberArea, 1e-20f);
                if (waste < bestWaste) bestWaste = waste, bestA = a, bestB = b;
            }
        mergeClusters(groups[bestA].cluster, groups[bestB].cluster);
        groups[bestA].coverage = groupCoverage(groups[bestA].cluster, o);
        groups.erase(groups.begin() + std::ptrdiff_t(bestB));
        ++merges;
    }
    return merges;
}

// The frustum of one layer of `light`, fitted to the group's sphere; false when the cone holds none of
// the group's members after all.
bool fitLayer(CausticMapGpu& m, const scene::Light& light, const SpecularCluster& group, const SpecularBounds& bounds,
              const std::vector<int32_t>& sphereOfInstance) {
    // The frustum is fitted to the sphere around the members' joint bounding box (for one cluster of all
    // specular instances, the one map per light of before, texel for texel).
    glm::vec3 lo(1e30f), hi(-1e30f);
    for (uint32_t inst : group.instances) {
        lo = glm::min(lo, bounds.instanceLo[size_t(sphereOfInstance[inst])]);
        hi = glm::max(hi, bounds.instanceHi[size_t(sphereOfInstance[inst])]);
    }
    const glm::vec4 fitted = sphereOf(lo, hi);
    const glm::vec3 centre(fitted);
    const float radius = std::max(fitted.w, 1e-4f);
    m.intensity = light.color * light.intensity;
    m.range = light.type == scene::LightType::Directional ? 0.0f : std::max(light.range, 0.0f);
    glm::vec3 dir = glm::normalize(light.direction);
    if (light.type == scene::LightType::Directional) {
        m.orthographic = 1;
        setFrame(m, dir);
        m.extent = radius * 1.001f;
        // The map plane sits outside the whole scene so that every occluder between the light and
        // the specular objects is rasterised in front of them.
        float back = glm::length(centre - bounds.sceneCentre) + bounds.sceneRadius + 0.01f;
        m.origin = centre - m.forward * back;
        m.nearPlane = 0.0f;
        m.viewProj = mapViewProj(m, back + radius);
        return true;
    }
    const bool spot = light.type == scene::LightType::Spot;
    if (spot) {
        m.spotAxis = dir;
        m.cosInner = std::cos(light.innerConeAngle);
        m.cosOuter = std::cos(light.outerConeAngle);
    }
    m.origin = light.position;
    glm::vec3 toTarget = centre - light.position;
    float distance = glm::length(toTarget);
    float halfAngle = kWideHalfAngle;
    glm::vec3 axis = distance > 0.0f ? toTarget / distance : (spot ? dir : glm::vec3(0, -1, 0));
    if (distance > 1.001f * radius) halfAngle = std::asin(radius / distance);
    if (spot && halfAngle >= light.outerConeAngle) {
        // The cone is the tighter frustum (texels outside the cone get zero falloff anyway).
        axis = dir;
        halfAngle = std::min(light.outerConeAngle, kWideHalfAngle);
    }
    bool any = false;
    for (uint32_t inst : group.instances) {
        const glm::vec4 s = bounds.instanceSpheres[size_t(sphereOfInstance[inst])];
        bool inFrustum = coneTouchesSphere(light.position, axis, halfAngle, s);
        bool inCone = !spot || coneTouchesSphere(light.position, dir, light.outerConeAngle, s);
        any = any || (inFrustum && inCone);
    }
    if (!any) return false;
    setFrame(m, axis);
    // The square frustum circumscribes the fitted cone: tan(half-angle) per side.
    m.extent = std::tan(halfAngle);
    m.nearPlane = std::max(1e-3f, 1e-5f * (distance + radius));
    m.viewProj = mapViewProj(m, distance + radius * 1.01f + 1e-3f);
    return true;
}

}  // namespace

CausticMapPlan planCausticMaps(const scene::Scene& scene, const SpecularBounds& bounds, bool drawOccluders) {
    CausticPlanOptions o;
    o.drawOccluders = drawOccluders;
    return planCausticMaps(scene, bounds, o);
}

CausticMapPlan planCausticMaps(const scene::Scene& scene, const SpecularBounds& bounds, const CausticPlanOptions& o) {
    CausticMapPlan plan;
    plan.instanceCount = uint32_t(scene.instances.size());
    auto skip = [&](uint32_t l, std::string why) {
        plan.skippedLights.push_back(l);
        plan.skipReasons.push_back(std::move(why));
    };
    std::vector<int32_t> sphereOfInstance(scene.instances.size(), -1);
    for (size_t i = 0; i < bounds.specularInstances.size(); ++i)
        if (bounds.specularInstances[i] < sphereOfInstance.size()) sphereOfInstance[bounds.specularInstances[i]] = int32_t(i);
    const std::vector<SpecularCluster> clusters = clusterSpecularInstances(bounds.instanceSpheres, bounds.specularInstances);
    std::vector<float> coverage;
    for (const SpecularCluster& c : clusters) coverage.push_back(groupCoverage(c, o));

    std::vector<uint32_t> layerLights;
    std::vector<std::vector<LayerGroup>> perLight;
    for (uint32_t l = 0; l < scene.lights.size(); ++l) {
        const scene::Light& light = scene.lights[l];
        if (bounds.empty()) { skip(l, "the scene has no specular instance"); continue; }
        if (l >= kMaxCausticLights) { skip(l, "more than kMaxCausticLights lights"); continue; }
        if (!(light.intensity > 0.0f) || glm::length(light.color) <= 0.0f) { skip(l, "emits nothing"); continue; }
        std::vector<LayerGroup> groups;
        uint32_t hidden = 0;
        for (size_t c = 0; c < clusters.size(); ++c) {
            if (!lightReaches(light, clusters[c], bounds, sphereOfInstance)) continue;
            if (coverage[c] <= 0.0f) { ++hidden; continue; }
            groups.push_back({clusters[c], coverage[c]});
        }
        plan.hiddenClusters += hidden;
        if (groups.empty()) {
            skip(l, hidden > 0 ? "the caustics of the " + std::to_string(hidden) +
                                     " specular clusters it reaches cannot reach the view"
                               : "no specular instance inside its frustum/cone/range");
            continue;
        }
        layerLights.push_back(l);
        perLight.push_back(std::move(groups));
    }
    plan.capMerges = capLayers(perLight, o);

    uint32_t row = 0;
    for (size_t i = 0; i < layerLights.size(); ++i) {
        const uint32_t l = layerLights[i];
        bool any = false;
        uint32_t cluster = 0;
        for (const LayerGroup& g : perLight[i]) {
            CausticMapGpu m;
            m.light = l;
            if (!fitLayer(m, scene.lights[l], g.cluster, bounds, sphereOfInstance)) continue;
            if (!any) plan.instanceLayers.resize(plan.instanceLayers.size() + plan.instanceCount, 0u);
            any = true;
            m.cluster = cluster++;
            m.ownerRow = row;
            for (uint32_t inst : g.cluster.instances) plan.instanceLayers[size_t(row) * plan.instanceCount + inst] = m.cluster + 1;
            plan.maps.push_back(m);
            plan.drawnInstances.push_back(instancesInFrustum(m, bounds, o.drawOccluders));
            plan.layerInstances.push_back(g.cluster.instances);
            plan.coverage.push_back(g.coverage);
        }
        if (any) ++row;
        else skip(l, "no specular instance inside its frustum/cone");
    }

    if (o.photons > 0 && !plan.maps.empty()) {
        double sum = 0.0;
        for (float c : plan.coverage) sum += c;
        for (size_t k = 0; k < plan.maps.size(); ++k)
            plan.maps[k].photons = float(double(o.photons) * plan.coverage[k] / sum);
        plan.photonBudget = o.photons;
    }
    return plan;
}

}  // namespace caustics
