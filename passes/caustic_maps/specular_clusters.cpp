// Clustering of the specular instances into caustic map layers (caustics/specular_clusters.h).
#include "caustics/specular_clusters.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <map>
#include <tuple>

namespace caustics {
namespace {

// merged radius^2 / summed member area: 1 for a perfect fit, the merge criterion's left side.
float mergeWaste(const SpecularCluster& a, const SpecularCluster& b) {
    const float r = enclosingSphere(a.sphere, b.sphere).w;
    return r * r / std::max(a.memberArea + b.memberArea, 1e-20f);
}

// Pools instances per grid cell when there are more than kMaxClusterSeeds of them: the cell side starts
// at the cube root of volume / seeds (flat layouts make that tiny) and doubles until at most
// kMaxClusterSeeds cells are occupied.
std::vector<SpecularCluster> seedClusters(const std::vector<glm::vec4>& spheres, const std::vector<uint32_t>& instances) {
    auto single = [&](size_t i) {
        SpecularCluster c;
        c.sphere = spheres[i];
        c.memberArea = spheres[i].w * spheres[i].w;
        c.instances = {instances[i]};
        return c;
    };
    std::vector<SpecularCluster> seeds;
    if (spheres.size() <= kMaxClusterSeeds) {
        for (size_t i = 0; i < spheres.size(); ++i) seeds.push_back(single(i));
        return seeds;
    }
    glm::vec3 lo(std::numeric_limits<float>::max()), hi(-std::numeric_limits<float>::max());
    for (const glm::vec4& s : spheres) {
        lo = glm::min(lo, glm::vec3(s));
        hi = glm::max(hi, glm::vec3(s));
    }
    const glm::vec3 extent = glm::max(hi - lo, glm::vec3(1e-3f));
    float cell = std::cbrt(extent.x * extent.y * extent.z / float(kMaxClusterSeeds));
    for (;; cell *= 2.0f) {
        std::map<std::tuple<int, int, int>, size_t> cells;
        seeds.clear();
        for (size_t i = 0; i < spheres.size(); ++i) {
            const glm::ivec3 c = glm::ivec3(glm::floor((glm::vec3(spheres[i]) - lo) / cell));
            auto [it, fresh] = cells.try_emplace({c.x, c.y, c.z}, seeds.size());
            if (fresh) seeds.push_back(single(i));
            else mergeClusters(seeds[it->second], single(i));
        }
        if (seeds.size() <= kMaxClusterSeeds) return seeds;
    }
}

}  // namespace

glm::vec4 enclosingSphere(glm::vec4 a, glm::vec4 b) {
    const glm::vec3 d = glm::vec3(b) - glm::vec3(a);
    const float dist = glm::length(d);
    if (dist + b.w <= a.w) return a;
    if (dist + a.w <= b.w) return b;
    const float r = 0.5f * (dist + a.w + b.w);
    // Centre on the segment between the two, r - a.w from a's centre (dist > 0 here).
    return glm::vec4(glm::vec3(a) + d * ((r - a.w) / dist), r);
}

bool clustersShareALayer(const SpecularCluster& a, const SpecularCluster& b, float ratio) {
    return mergeWaste(a, b) <= ratio;
}

void mergeClusters(SpecularCluster& a, const SpecularCluster& b) {
    a.sphere = enclosingSphere(a.sphere, b.sphere);
    a.memberArea += b.memberArea;
    a.instances.insert(a.instances.end(), b.instances.begin(), b.instances.end());
    std::sort(a.instances.begin(), a.instances.end());
}

std::vector<SpecularCluster> clusterSpecularInstances(const std::vector<glm::vec4>& spheres,
                                                      const std::vector<uint32_t>& instances, float ratio) {
    std::vector<SpecularCluster> clusters = seedClusters(spheres, instances);
    std::vector<bool> alive(clusters.size(), true);
    // Each cluster's best partner (lowest waste) among the live ones; recomputed for the clusters a merge
    // touched. O(n^2) per merge in the worst case, n <= kMaxClusterSeeds.
    std::vector<std::pair<float, size_t>> best(clusters.size(), {std::numeric_limits<float>::max(), 0});
    auto refresh = [&](size_t i) {
        best[i] = {std::numeric_limits<float>::max(), i};
        for (size_t j = 0; j < clusters.size(); ++j)
            if (j != i && alive[j]) best[i] = std::min(best[i], {mergeWaste(clusters[i], clusters[j]), j});
    };
    for (size_t i = 0; i < clusters.size(); ++i) refresh(i);
    for (;;) {
        size_t a = clusters.size();
        for (size_t i = 0; i < clusters.size(); ++i)
            if (alive[i] && best[i].first <= ratio && (a == clusters.size() || best[i] < best[a])) a = i;
        if (a == clusters.size()) break;
        const size_t b = best[a].second;
        mergeClusters(clusters[a], clusters[b]);
        alive[b] = false;
        for (size_t i = 0; i < clusters.size(); ++i) {
            if (!alive[i]) continue;
            if (i == a || best[i].second == a || best[i].second == b) refresh(i);
            // The grown cluster can fit i better than i's old partner did (a member added inside a's
            // sphere adds area but no radius).
            else best[i] = std::min(best[i], {mergeWaste(clusters[i], clusters[a]), a});
        }
    }
    std::vector<SpecularCluster> out;
    for (size_t i = 0; i < clusters.size(); ++i)
        if (alive[i]) out.push_back(std::move(clusters[i]));
    // Deterministic order: by first member.
    std::sort(out.begin(), out.end(), [](const SpecularCluster& x, const SpecularCluster& y) {
        return x.instances.front() < y.instances.front();
    });
    return out;
}

}  // namespace caustics
