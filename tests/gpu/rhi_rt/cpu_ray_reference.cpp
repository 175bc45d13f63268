#include "cpu_ray_reference.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace caustics::test {
namespace {

Vec3 sub(const Vec3& a, const Vec3& b) { return {a[0] - b[0], a[1] - b[1], a[2] - b[2]}; }
Vec3 cross(const Vec3& a, const Vec3& b) {
    return {a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]};
}
double dot(const Vec3& a, const Vec3& b) { return a[0] * b[0] + a[1] * b[1] + a[2] * b[2]; }

Vec3 apply(const Transform& m, const float* p) {
    Vec3 r;
    for (int i = 0; i < 3; ++i) r[i] = double(m[i][0]) * p[0] + double(m[i][1]) * p[1] + double(m[i][2]) * p[2] + m[i][3];
    return r;
}

using Mat3 = std::array<std::array<double, 3>, 3>;
Mat3 multiply(const Mat3& a, const Mat3& b) {
    Mat3 r{};
    for (int i = 0; i < 3; ++i)
        for (int j = 0; j < 3; ++j)
            for (int k = 0; k < 3; ++k) r[i][j] += a[i][k] * b[k][j];
    return r;
}

}  // namespace

Transform makeTransform(double rotX, double rotY, double rotZ, Vec3 scale, Vec3 translation) {
    const double cx = std::cos(rotX), sx = std::sin(rotX), cy = std::cos(rotY), sy = std::sin(rotY);
    const double cz = std::cos(rotZ), sz = std::sin(rotZ);
    Mat3 rx{{{1, 0, 0}, {0, cx, -sx}, {0, sx, cx}}};
    Mat3 ry{{{cy, 0, sy}, {0, 1, 0}, {-sy, 0, cy}}};
    Mat3 rz{{{cz, -sz, 0}, {sz, cz, 0}, {0, 0, 1}}};
    Mat3 s{{{scale[0], 0, 0}, {0, scale[1], 0}, {0, 0, scale[2]}}};
    Mat3 m = multiply(rz, multiply(ry, multiply(rx, s)));
    Transform t{};
    for (int i = 0; i < 3; ++i) {
        for (int j = 0; j < 3; ++j) t[i][j] = float(m[i][j]);
        t[i][3] = float(translation[i]);
    }
    return t;
}

void writeTransform(const Transform& t, rhi::InstanceDesc& instance) {
    for (int i = 0; i < 3; ++i)
        for (int j = 0; j < 4; ++j) instance.transform[i][j] = t[i][j];
}

CpuHit traceCpu(const std::vector<CpuInstance>& instances, const Vec3& origin, const Vec3& direction,
                double tMin, double tMax, double edgeEpsilon, const std::vector<uint32_t>& candidates) {
    CpuHit best;
    best.t = std::numeric_limits<double>::infinity();
    double secondT = std::numeric_limits<double>::infinity();
    bool nearEdge = false;
    auto visit = [&](const CpuInstance& inst) {
        const CpuMesh& mesh = *inst.mesh;
        for (uint32_t tri = 0; tri < mesh.triangleCount(); ++tri) {
            Vec3 v[3];
            for (int k = 0; k < 3; ++k) v[k] = apply(inst.transform, &mesh.positions[3 * mesh.indices[3 * tri + k]]);
            const Vec3 e1 = sub(v[1], v[0]), e2 = sub(v[2], v[0]);
            const Vec3 p = cross(direction, e2);
            const double det = dot(e1, p);
            if (std::abs(det) < 1e-300) continue;   // ray parallel to the triangle's plane
            const double inv = 1.0 / det;
            const Vec3 s = sub(origin, v[0]);
            const double u = dot(s, p) * inv;
            const Vec3 q = cross(s, e1);
            const double w = dot(direction, q) * inv;
            const double t = dot(e2, q) * inv;
            const double edge = std::min({u, w, 1.0 - u - w});
            // Relative slack on t for rays that end (or start) right at a surface.
            const double tSlack = edgeEpsilon * std::max(1.0, std::abs(t));
            if (t < tMin - tSlack || t > tMax + tSlack) continue;
            if (std::abs(edge) <= edgeEpsilon) nearEdge = true;
            if (edge < 0 || t < tMin || t > tMax) continue;
            if (t < best.t) {
                secondT = best.t;
                best.hit = true;
                best.t = t;
                best.instanceId = inst.instanceId;
                best.primitiveId = tri;
            } else {
                secondT = std::min(secondT, t);
            }
        }
    };
    if (candidates.empty()) {
        for (const CpuInstance& inst : instances) visit(inst);
    } else {
        for (uint32_t i : candidates) visit(instances[i]);
    }
    best.ambiguous = nearEdge || (best.hit && secondT - best.t <= edgeEpsilon * std::max(1.0, best.t));
    return best;
}

CpuMesh makeTerrain(uint32_t cells, float amplitude) {
    CpuMesh mesh;
    const uint32_t n = cells + 1;
    for (uint32_t y = 0; y < n; ++y) {
        for (uint32_t x = 0; x < n; ++x) {
            const float fx = -1.0f + 2.0f * float(x) / float(cells);
            const float fy = -1.0f + 2.0f * float(y) / float(cells);
            mesh.positions.insert(mesh.positions.end(),
                                  {fx, fy, amplitude * std::sin(3.0f * fx) * std::cos(2.0f * fy)});
        }
    }
    for (uint32_t y = 0; y < cells; ++y) {
        for (uint32_t x = 0; x < cells; ++x) {
            const uint32_t i = y * n + x;
            mesh.indices.insert(mesh.indices.end(), {i, i + 1, i + n + 1, i, i + n + 1, i + n});
        }
    }
    return mesh;
}

CpuMesh makeQuad(float h) {
    CpuMesh mesh;
    mesh.positions = {-h, -h, 0, h, -h, 0, h, h, 0, -h, h, 0};
    mesh.indices = {0, 1, 2, 0, 2, 3};
    return mesh;
}

}  // namespace caustics::test
