#pragma once
// Groups of specular instances that share one caustic map layer (docs/caustics.md, "Layers per
// cluster"). One map fitted to every specular object of a level spreads a light's texels over the
// whole level, so a ball's photon density would depend on where the other glass stands. Instead the
// specular instances are clustered by their world bounding spheres: two groups share a layer only while
// the sphere around both stays within kClusterMergeAreaRatio times the summed cross-section of their
// members (a layer spends at most that many texels per texel its objects cover); farther apart, each
// group gets a layer of its own, fitted to it.
#include <cstdint>
#include <vector>

#include <glm/glm.hpp>

namespace caustics {

// A merged layer may spend up to this factor of texels over the cross-section its objects cover
// (4: three objects of a table top share a layer; two balls a few radii apart do not).
inline constexpr float kClusterMergeAreaRatio = 4.0f;
// Above this many specular instances, instances are first pooled per cell of a uniform grid, so the
// pairwise merge stays O(n^2) in at most this many groups (per frame, on the CPU).
inline constexpr uint32_t kMaxClusterSeeds = 1024;

struct SpecularCluster {
    glm::vec4 sphere{0.0f};              // xyz centre, w radius: encloses every member's sphere
    float memberArea = 0.0f;             // sum of the members' radius^2 (cross-section / pi)
    std::vector<uint32_t> instances;     // scene instance indices, ascending
};

// The smallest sphere enclosing spheres a and b (xyz centre, w radius).
glm::vec4 enclosingSphere(glm::vec4 a, glm::vec4 b);

// Would a and b share a layer (the merged sphere's radius^2 within ratio x their summed member area)?
bool clustersShareALayer(const SpecularCluster& a, const SpecularCluster& b, float ratio = kClusterMergeAreaRatio);

// Merges b into a (sphere, area, members).
void mergeClusters(SpecularCluster& a, const SpecularCluster& b);

// spheres[i] bounds scene instance instances[i]. Agglomerative: the pair whose merged sphere wastes the
// least (merged radius^2 / member area) merges first, while clustersShareALayer holds. Deterministic:
// the result depends only on the input order and values.
std::vector<SpecularCluster> clusterSpecularInstances(const std::vector<glm::vec4>& spheres,
                                                      const std::vector<uint32_t>& instances,
                                                      float ratio = kClusterMergeAreaRatio);

}  // namespace caustics
