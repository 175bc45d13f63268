#pragma once
// Bounding volume hierarchy over world-space triangles, built with binned SAH (Wald 2007, "On fast
// construction of SAH-based bounding volume hierarchies"), for the CPU reference tracer.
#include <cstdint>
#include <span>
#include <vector>

#include <glm/glm.hpp>

namespace caustics::reference {

struct Triangle {
    glm::vec3 p0, p1, p2;
};

struct RayHit {
    float t = 0.0f;
    uint32_t triangle = 0;
    float u = 0.0f, v = 0.0f;  // barycentrics of p1 and p2
};

class TriangleBvh {
public:
    // Keeps a copy of the triangles; indices in RayHit refer to the order given here.
    explicit TriangleBvh(std::span<const Triangle> triangles);

    // Closest hit with t in (tMin, tMax).
    bool intersect(const glm::vec3& origin, const glm::vec3& dir, float tMin, float tMax, RayHit& hit) const;
    // Any hit with t in (tMin, tMax).
    bool occluded(const glm::vec3& origin, const glm::vec3& dir, float tMin, float tMax) const;

    size_t nodeCount() const { return nodes_.size(); }
    glm::vec3 boundsMin() const;
    glm::vec3 boundsMax() const;

private:
    struct Node {
        glm::vec3 min;
        uint32_t firstOrChild;  // leaf: first index into order_; inner: left child (right = left + 1)
        glm::vec3 max;
        uint32_t count;         // > 0: leaf
    };
    void build(uint32_t nodeIndex, uint32_t first, uint32_t count, uint32_t depth, std::vector<glm::vec3>& centroids);
    template <bool AnyHit>
    bool traverse(const glm::vec3& origin, const glm::vec3& dir, float tMin, float tMax, RayHit* hit) const;

    std::vector<Triangle> triangles_;
    std::vector<uint32_t> order_;
    std::vector<Node> nodes_;
};

}  // namespace caustics::reference
