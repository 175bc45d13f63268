#include "caustics/reference/bvh.h"

#include <algorithm>
#include <array>
#include <limits>

namespace caustics::reference {
namespace {

constexpr uint32_t kBins = 16;
constexpr uint32_t kMaxLeafSize = 4;
constexpr float kTraversalCost = 1.0f;  // relative to one triangle test
constexpr uint32_t kMaxDepth = 60;

struct Aabb {
    glm::vec3 min{std::numeric_limits<float>::max()};
    glm::vec3 max{-std::numeric_limits<float>::max()};
    void grow(const glm::vec3& p) { min = glm::min(min, p); max = glm::max(max, p); }
    void grow(const Aabb& b) { min = glm::min(min, b.min); max = glm::max(max, b.max); }
    float area() const {
        glm::vec3 e = glm::max(max - min, glm::vec3(0.0f));
        return 2.0f * (e.x * e.y + e.y * e.z + e.z * e.x);
    }
};

Aabb triangleBounds(const Triangle& t) {
    Aabb b;
    b.grow(t.p0);
    b.grow(t.p1);
    b.grow(t.p2);
    return b;
}

// Moller-Trumbore (1997), double-sided.
bool intersectTriangle(const Triangle& tri, const glm::vec3& o, const glm::vec3& d, float tMin, float tMax,
                       float& t, float& u, float& v) {
    glm::vec3 e1 = tri.p1 - tri.p0;
    glm::vec3 e2 = tri.p2 - tri.p0;
    glm::vec3 p = glm::cross(d, e2);
    float det = glm::dot(e1, p);
    if (std::abs(det) < 1e-20f) return false;
    float inv = 1.0f / det;
    glm::vec3 s = o - tri.p0;
    u = glm::dot(s, p) * inv;
    if (u < 0.0f || u > 1.0f) return false;
    glm::vec3 q = glm::cross(s, e1);
    v = glm::dot(d, q) * inv;
    if (v < 0.0f || u + v > 1.0f) return false;
    t = glm::dot(e2, q) * inv;
    return t > tMin && t < tMax;
}

bool intersectBox(const glm::vec3& bmin, const glm::vec3& bmax, const glm::vec3& o, const glm::vec3& invD,
                  float tMin, float tMax, float& tEnter) {
    glm::vec3 t0 = (bmin - o) * invD;
    glm::vec3 t1 = (bmax - o) * invD;
    glm::vec3 lo = glm::min(t0, t1);
    glm::vec3 hi = glm::max(t0, t1);
    float enter = std::max(std::max(lo.x, lo.y), std::max(lo.z, tMin));
    float exit = std::min(std::min(hi.x, hi.y), std::min(hi.z, tMax));
    tEnter = enter;
    return enter <= exit;
}

}  // namespace

TriangleBvh::TriangleBvh(std::span<const Triangle> triangles) : triangles_(triangles.begin(), triangles.end()) {
    order_.resize(triangles_.size());
    std::vector<glm::vec3> centroids(triangles_.size());
    for (uint32_t i = 0; i < triangles_.size(); ++i) {
        order_[i] = i;
        centroids[i] = (triangles_[i].p0 + triangles_[i].p1 + triangles_[i].p2) / 3.0f;
    }
    nodes_.reserve(2 * triangles_.size() + 1);
    nodes_.push_back({});
    if (!triangles_.empty()) {
        build(0, 0, uint32_t(triangles_.size()), 0, centroids);
    } else {
        nodes_[0] = Node{glm::vec3(0.0f), 0, glm::vec3(-1.0f), 0};
    }
}

glm::vec3 TriangleBvh::boundsMin() const { return nodes_[0].min; }
glm::vec3 TriangleBvh::boundsMax() const { return nodes_[0].max; }

// Builds the subtree of order_[first, first+count) into the (already allocated) slot nodeIndex.
void TriangleBvh::build(uint32_t nodeIndex, uint32_t first, uint32_t count, uint32_t depth,
                        std::vector<glm::vec3>& centroids) {
    Aabb bounds, centroidBounds;
    for (uint32_t i = first; i < first + count; ++i) {
        bounds.grow(triangleBounds(triangles_[order_[i]]));
        centroidBounds.grow(centroids[order_[i]]);
    }
    auto makeLeaf = [&] { nodes_[nodeIndex] = Node{bounds.min, first, bounds.max, count}; };
    // The depth cap keeps the traversal stack (kMaxDepth + 1 entries) from overflowing.
    if (count <= kMaxLeafSize || depth >= kMaxDepth) return makeLeaf();

    // Binned SAH over all three axes; cost = C_trav + (A_L N_L + A_R N_R) / A.
    float bestCost = std::numeric_limits<float>::max();
    int bestAxis = -1;
    uint32_t bestSplit = 0;
    glm::vec3 extent = centroidBounds.max - centroidBounds.min;
    for (int axis = 0; axis < 3; ++axis) {
        if (extent[axis] <= 0.0f) continue;
        std::array<Aabb, kBins> binBounds{};
        std::array<uint32_t, kBins> binCount{};
        float scale = float(kBins) / extent[axis];
        for (uint32_t i = first; i < first + count; ++i) {
            uint32_t b = std::min(kBins - 1, uint32_t((centroids[order_[i]][axis] - centroidBounds.min[axis]) * scale));
            binBounds[b].grow(triangleBounds(triangles_[order_[i]]));
            ++binCount[b];
        }
        std::array<float, kBins> rightCost{};
        Aabb acc;
        uint32_t n = 0;
        for (uint32_t b = kBins - 1; b > 0; --b) {
            acc.grow(binBounds[b]);
            n += binCount[b];
            rightCost[b] = n ? acc.area() * float(n) : 0.0f;
        }
        acc = Aabb{};
        n = 0;
        for (uint32_t b = 0; b + 1 < kBins; ++b) {
            acc.grow(binBounds[b]);
            n += binCount[b];
            float cost = (n ? acc.area() * float(n) : 0.0f) + rightCost[b + 1];
            if (cost < bestCost) { bestCost = cost; bestAxis = axis; bestSplit = b + 1; }
        }
    }
    float leafCost = float(count);
    // Split only when SAH says it pays, but never keep leaves larger than 16 triangles.
    if (bestAxis < 0) return makeLeaf();
    if (kTraversalCost + bestCost / bounds.area() >= leafCost && count <= 16) return makeLeaf();
    float scale = float(kBins) / extent[bestAxis];
    auto mid = std::partition(order_.begin() + first, order_.begin() + first + count, [&](uint32_t idx) {
        uint32_t b = std::min(kBins - 1, uint32_t((centroids[idx][bestAxis] - centroidBounds.min[bestAxis]) * scale));
        return b < bestSplit;
    });
    uint32_t leftCount = uint32_t(mid - (order_.begin() + first));
    if (leftCount == 0 || leftCount == count) return makeLeaf();

    uint32_t left = uint32_t(nodes_.size());
    nodes_.push_back({});
    nodes_.push_back({});
    nodes_[nodeIndex] = Node{bounds.min, left, bounds.max, 0};
    build(left, first, leftCount, depth + 1, centroids);
    build(left + 1, first + leftCount, count - leftCount, depth + 1, centroids);
}

template <bool AnyHit>
bool TriangleBvh::traverse(const glm::vec3& o, const glm::vec3& d, float tMin, float tMax, RayHit* hit) const {
    if (nodes_.empty() || triangles_.empty()) return false;
    glm::vec3 invD = 1.0f / d;
    uint32_t stack[kMaxDepth + 4];
    uint32_t sp = 0;
    stack[sp++] = 0;
    bool found = false;
    float closest = tMax;
    while (sp > 0) {
        const Node& node = nodes_[stack[--sp]];
        float tEnter;
        if (!intersectBox(node.min, node.max, o, invD, tMin, closest, tEnter)) continue;
        if (node.count > 0) {
            for (uint32_t i = node.firstOrChild; i < node.firstOrChild + node.count; ++i) {
                float t, u, v;
                if (intersectTriangle(triangles_[order_[i]], o, d, tMin, closest, t, u, v)) {
                    if constexpr (AnyHit) return true;
                    found = true;
                    closest = t;
                    *hit = RayHit{t, order_[i], u, v};
                }
            }
            continue;
        }
        uint32_t a = node.firstOrChild, b = node.firstOrChild + 1;
        float ta, tb;
        bool ha = intersectBox(nodes_[a].min, nodes_[a].max, o, invD, tMin, closest, ta);
        bool hb = intersectBox(nodes_[b].min, nodes_[b].max, o, invD, tMin, closest, tb);
        // Push the far child first so the near one is visited first.
        if (ha && hb) {
            if (ta < tb) std::swap(a, b);
            stack[sp++] = a;
            stack[sp++] = b;
        } else if (ha) {
            stack[sp++] = a;
        } else if (hb) {
            stack[sp++] = b;
        }
    }
    return found;
}

bool TriangleBvh::intersect(const glm::vec3& o, const glm::vec3& d, float tMin, float tMax, RayHit& hit) const {
    return traverse<false>(o, d, tMin, tMax, &hit);
}

bool TriangleBvh::occluded(const glm::vec3& o, const glm::vec3& d, float tMin, float tMax) const {
    return traverse<true>(o, d, tMin, tMax, nullptr);
}

}  // namespace caustics::reference
