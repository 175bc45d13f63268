// Procedural shapes. Surfaces of revolution are built from profiles in the (r, y) half-plane: a
// profile point's surface normal is d(profile) x d(theta), so walking the profile "up the outside"
// gives outward normals (checked by the unit tests' closed-mesh orientation test).
#include "caustics/scene/mesh_builder.h"

#include <cmath>

#include "caustics/scene/mesh_utils.h"

namespace caustics::scene {

namespace {

constexpr float kPi = 3.14159265358979f;

struct ProfilePoint {
    float r, y;     // radius, height
    float nr, ny;   // normal in the (r, y) plane
    float v;        // texture v
};

// Revolves one smooth strip of profile points around +Y with `segments` segments (seam duplicated).
void revolve(Mesh& mesh, const std::vector<ProfilePoint>& strip, uint32_t segments) {
    uint32_t base = uint32_t(mesh.positions.size());
    for (const ProfilePoint& p : strip)
        for (uint32_t j = 0; j <= segments; ++j) {
            float theta = 2.0f * kPi * float(j) / float(segments);
            float c = std::cos(theta), s = std::sin(theta);
            mesh.positions.push_back({p.r * c, p.y, p.r * s});
            mesh.normals.push_back(glm::normalize(glm::vec3(p.nr * c, p.ny, p.nr * s) + glm::vec3(0.0f, 1e-12f, 0.0f)));
            mesh.uvs.push_back({float(j) / float(segments), p.v});
        }
    uint32_t row = segments + 1;
    for (uint32_t i = 0; i + 1 < strip.size(); ++i)
        for (uint32_t j = 0; j < segments; ++j) {
            uint32_t a = base + i * row + j, b = base + (i + 1) * row + j;
            mesh.indices.insert(mesh.indices.end(), {a, b, a + 1, b, b + 1, a + 1});
        }
}

// A flat ring/disc strip from radius r0 to r1 at height y with normal (0, ny).
void revolveFlat(Mesh& mesh, float r0, float r1, float y, float ny, uint32_t segments) {
    revolve(mesh, {{r0, y, 0.0f, ny, 0.0f}, {r1, y, 0.0f, ny, 1.0f}}, segments);
}

// A vertical wall strip from y0 to y1 at radius r with normal (nr, 0), `rings` rows.
void revolveWall(Mesh& mesh, float r, float y0, float y1, float nr, uint32_t segments, uint32_t rings) {
    std::vector<ProfilePoint> strip;
    for (uint32_t i = 0; i <= rings; ++i) {
        float t = float(i) / float(rings);
        strip.push_back({r, y0 + (y1 - y0) * t, nr, 0.0f, t});
    }
    revolve(mesh, strip, segments);
}

// Quad p0..p3 (cyclic); flipped if needed so its front face looks along n.
void addQuad(Mesh& mesh, glm::vec3 p0, glm::vec3 p1, glm::vec3 p2, glm::vec3 p3, const glm::vec3& n,
             const glm::vec2 uv[4]) {
    bool flip = glm::dot(glm::cross(p1 - p0, p2 - p0), n) < 0.0f;
    uint32_t base = uint32_t(mesh.positions.size());
    glm::vec3 p[4] = {p0, p1, p2, p3};
    for (int k = 0; k < 4; ++k) {
        mesh.positions.push_back(p[k]);
        mesh.normals.push_back(n);
        mesh.uvs.push_back(uv[k]);
    }
    if (flip) mesh.indices.insert(mesh.indices.end(), {base, base + 2, base + 1, base, base + 3, base + 2});
    else mesh.indices.insert(mesh.indices.end(), {base, base + 1, base + 2, base, base + 2, base + 3});
}

}  // namespace

void appendMesh(Mesh& dst, const Mesh& src, const glm::mat4& transform) {
    uint32_t base = uint32_t(dst.positions.size());
    glm::mat3 nm = normalMatrix(transform);
    for (size_t i = 0; i < src.positions.size(); ++i) {
        dst.positions.push_back(glm::vec3(transform * glm::vec4(src.positions[i], 1.0f)));
        dst.normals.push_back(i < src.normals.size() ? glm::normalize(nm * src.normals[i]) : glm::vec3(0, 1, 0));
        dst.uvs.push_back(i < src.uvs.size() ? src.uvs[i] : glm::vec2(0.0f));
    }
    for (uint32_t idx : src.indices) dst.indices.push_back(base + idx);
}

Mesh makeBox(const glm::vec3& h, float uvScale) {
    Mesh mesh;
    for (int axis = 0; axis < 3; ++axis)
        for (float sign : {-1.0f, 1.0f}) {
            glm::vec3 n(0.0f);
            n[axis] = sign;
            int u = (axis + 1) % 3, v = (axis + 2) % 3;
            glm::vec3 c = n * h;
            glm::vec3 du(0.0f), dv(0.0f);
            du[u] = h[u];
            dv[v] = h[v];
            float su = 2.0f * h[u] * uvScale, sv = 2.0f * h[v] * uvScale;
            glm::vec2 uv[4] = {{0, 0}, {su, 0}, {su, sv}, {0, sv}};
            addQuad(mesh, c - du - dv, c + du - dv, c + du + dv, c - du + dv, n, uv);
        }
    return mesh;
}

Mesh makePlane(float hx, float hz, uint32_t div, float uvScale) {
    Mesh mesh;
    div = std::max(div, 1u);
    for (uint32_t i = 0; i <= div; ++i)
        for (uint32_t j = 0; j <= div; ++j) {
            float x = -hx + 2.0f * hx * float(j) / float(div), z = -hz + 2.0f * hz * float(i) / float(div);
            mesh.positions.push_back({x, 0.0f, z});
            mesh.normals.push_back({0.0f, 1.0f, 0.0f});
            mesh.uvs.push_back({(x + hx) * uvScale, (z + hz) * uvScale});
        }
    // (x0,z0), (x0,z1), (x1,z0) is counter-clockwise seen from +Y.
    for (uint32_t i = 0; i < div; ++i)
        for (uint32_t j = 0; j < div; ++j) {
            uint32_t a = i * (div + 1) + j, b = a + div + 1;
            mesh.indices.insert(mesh.indices.end(), {a, b, a + 1, b, b + 1, a + 1});
        }
    return mesh;
}

Mesh makeSphere(float radius, uint32_t segments, uint32_t rings) {
    Mesh mesh;
    std::vector<ProfilePoint> strip;
    for (uint32_t i = 0; i <= rings; ++i) {
        float phi = -0.5f * kPi + kPi * float(i) / float(rings);
        strip.push_back({radius * std::cos(phi), radius * std::sin(phi), std::cos(phi), std::sin(phi), float(i) / float(rings)});
    }
    revolve(mesh, strip, segments);
    return mesh;
}

Mesh makeCylinder(float radius, float height, uint32_t segments, uint32_t rings, bool caps) {
    Mesh mesh;
    revolveWall(mesh, radius, 0.0f, height, 1.0f, segments, std::max(rings, 1u));
    if (caps) {
        revolveFlat(mesh, 0.0f, radius, 0.0f, -1.0f, segments);
        revolveFlat(mesh, radius, 0.0f, height, 1.0f, segments);
    }
    return mesh;
}

Mesh makeTube(float ro, float ri, float height, uint32_t segments, float bottom) {
    Mesh mesh;
    revolveWall(mesh, ro, 0.0f, height, 1.0f, segments, 1);       // outer wall, outward
    revolveFlat(mesh, ro, ri, height, 1.0f, segments);            // top rim, up
    revolveWall(mesh, ri, height, bottom, -1.0f, segments, 1);    // inner wall, toward the axis
    if (bottom > 0.0f) {
        revolveFlat(mesh, ri, 0.0f, bottom, 1.0f, segments);      // inner floor, up
        revolveFlat(mesh, 0.0f, ro, 0.0f, -1.0f, segments);       // base, down
    } else {
        revolveFlat(mesh, ri, ro, 0.0f, -1.0f, segments);         // bottom rim, down
    }
    return mesh;
}

Mesh makeTorus(float R, float r, uint32_t segments, uint32_t sides) {
    Mesh mesh;
    std::vector<ProfilePoint> strip;
    for (uint32_t i = 0; i <= sides; ++i) {
        float phi = 2.0f * kPi * float(i) / float(sides);
        strip.push_back({R + r * std::cos(phi), r * std::sin(phi), std::cos(phi), std::sin(phi), float(i) / float(sides)});
    }
    revolve(mesh, strip, segments);
    return mesh;
}

Mesh makeArch(float span, float top, float depth, uint32_t segments) {
    Mesh mesh;
    float a = 0.5f * span, hz = 0.5f * depth;
    auto arc = [&](uint32_t k) {   // from the left springing point (angle pi) to the right (0)
        float phi = kPi * (1.0f - float(k) / float(segments));
        return glm::vec2(a * std::cos(phi), a * std::sin(phi));
    };
    auto outer = [&](uint32_t k) {   // the same angle's point on the spandrel's outer rectangle
        glm::vec2 d = glm::normalize(arc(k));
        float tSide = std::abs(d.x) > 1e-6f ? a / std::abs(d.x) : 1e30f;
        float tTop = d.y > 1e-6f ? top / d.y : 1e30f;
        return d * std::min(tSide, tTop);
    };
    glm::vec2 uv[4] = {{0, 0}, {1, 0}, {1, 1}, {0, 1}};
    for (uint32_t k = 0; k < segments; ++k) {
        glm::vec2 i0 = arc(k), i1 = arc(k + 1), o0 = outer(k), o1 = outer(k + 1);
        for (float z : {-hz, hz}) {   // front and back faces
            glm::vec3 n(0.0f, 0.0f, z > 0.0f ? 1.0f : -1.0f);
            addQuad(mesh, {i0, z}, {o0, z}, {o1, z}, {i1, z}, n, uv);
        }
        glm::vec2 mid = 0.5f * (i0 + i1);
        glm::vec3 n = glm::normalize(glm::vec3(-mid, 0.0f));   // intrados faces the arch's centre
        addQuad(mesh, {i0, -hz}, {i1, -hz}, {i1, hz}, {i0, hz}, n, uv);
    }
    addQuad(mesh, {-a, top, -hz}, {a, top, -hz}, {a, top, hz}, {-a, top, hz}, {0.0f, 1.0f, 0.0f}, uv);
    return mesh;
}

}  // namespace caustics::scene
