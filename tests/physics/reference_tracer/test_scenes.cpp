#include "test_scenes.h"

#include <cmath>

#include "common/camera.h"

namespace caustics::physics {

scene::Material diffuseMaterial(float albedo) {
    scene::Material m;
    m.name = "diffuse";
    m.baseColor = glm::vec3(albedo);
    m.roughness = 1.0f;
    // Lambertian: no specular layer in the shared BRDF (shaders/common/bsdf.h), so rho E / pi is exact.
    m.specular = 0.0f;
    return m;
}

scene::Material glassMaterial(float ior) {
    scene::Material m;
    m.name = "glass";
    m.baseColor = glm::vec3(1.0f);
    m.roughness = 0.0f;
    m.transmission = 1.0f;
    m.ior = ior;
    m.thickness = 1.0f;  // a closed volume, not thin-walled
    return m;
}

scene::Material mirrorMetal(float reflectance) {
    scene::Material m;
    m.name = "metal";
    m.baseColor = glm::vec3(reflectance);
    m.metallic = 1.0f;
    m.roughness = 0.0f;
    return m;
}

uint32_t addObject(scene::Scene& s, scene::Mesh mesh, const scene::Material& material) {
    mesh.material = uint32_t(s.materials.size());
    s.materials.push_back(material);
    scene::Instance inst;
    inst.mesh = uint32_t(s.meshes.size());
    inst.objectId = uint32_t(s.instances.size());
    s.meshes.push_back(std::move(mesh));
    s.instances.push_back(inst);
    return inst.mesh;
}

scene::Mesh makeQuadY(float y, float x0, float x1, float z0, float z1) {
    scene::Mesh m;
    m.positions = {{x0, y, z0}, {x1, y, z0}, {x1, y, z1}, {x0, y, z1}};
    m.normals.assign(4, glm::vec3(0, 1, 0));
    m.indices = {0, 2, 1, 0, 3, 2};  // counter-clockwise seen from +y
    return m;
}

scene::Mesh makeBox(glm::vec3 lo, glm::vec3 hi) {
    scene::Mesh m;
    for (int axis = 0; axis < 3; ++axis) {
        for (int side = 0; side < 2; ++side) {
            glm::vec3 n(0.0f);
            n[axis] = side ? 1.0f : -1.0f;
            int a = (axis + 1) % 3, b = (axis + 2) % 3;
            uint32_t base = uint32_t(m.positions.size());
            for (int k = 0; k < 4; ++k) {
                glm::vec3 p;
                p[axis] = side ? hi[axis] : lo[axis];
                p[a] = (k == 1 || k == 2) ? hi[a] : lo[a];
                p[b] = (k >= 2) ? hi[b] : lo[b];
                m.positions.push_back(p);
                m.normals.push_back(n);
            }
            if (side) m.indices.insert(m.indices.end(), {base, base + 1, base + 2, base, base + 2, base + 3});
            else m.indices.insert(m.indices.end(), {base, base + 2, base + 1, base, base + 3, base + 2});
        }
    }
    return m;
}

scene::Mesh makeSphere(glm::vec3 centre, float radius, uint32_t segments, uint32_t rings) {
    scene::Mesh m;
    // Poles on the x axis, so that rays along y meet well-shaped quads near the "equator".
    for (uint32_t r = 0; r <= rings; ++r) {
        float theta = float(M_PI) * float(r) / float(rings);
        for (uint32_t s = 0; s <= segments; ++s) {
            float phi = 2.0f * float(M_PI) * float(s) / float(segments);
            glm::vec3 n(std::cos(theta), std::sin(theta) * std::cos(phi), std::sin(theta) * std::sin(phi));
            m.positions.push_back(centre + radius * n);
            m.normals.push_back(n);
        }
    }
    for (uint32_t r = 0; r < rings; ++r) {
        for (uint32_t s = 0; s < segments; ++s) {
            uint32_t i0 = r * (segments + 1) + s, i1 = i0 + 1, i2 = i0 + segments + 1, i3 = i2 + 1;
            m.indices.insert(m.indices.end(), {i0, i2, i1, i1, i2, i3});
        }
    }
    return m;
}

scene::Mesh makeCylinderBand(float radius, float y0, float y1, uint32_t segments) {
    scene::Mesh m;
    for (uint32_t s = 0; s <= segments; ++s) {
        float phi = 2.0f * float(M_PI) * float(s) / float(segments);
        glm::vec3 n(std::cos(phi), 0.0f, std::sin(phi));
        m.positions.push_back(glm::vec3(radius * n.x, y0, radius * n.z));
        m.positions.push_back(glm::vec3(radius * n.x, y1, radius * n.z));
        m.normals.insert(m.normals.end(), {n, n});
    }
    for (uint32_t s = 0; s < segments; ++s) {
        uint32_t a = 2 * s, b = a + 1, c = a + 2, d = a + 3;
        m.indices.insert(m.indices.end(), {a, b, c, c, b, d});
    }
    return m;
}

scene::Mesh makeAnnulusY(float y, float inner, float outer, uint32_t segments) {
    scene::Mesh m;
    for (uint32_t s = 0; s <= segments; ++s) {
        float phi = 2.0f * float(M_PI) * float(s) / float(segments);
        glm::vec2 d(std::cos(phi), std::sin(phi));
        m.positions.push_back(glm::vec3(inner * d.x, y, inner * d.y));
        m.positions.push_back(glm::vec3(outer * d.x, y, outer * d.y));
        m.normals.insert(m.normals.end(), {glm::vec3(0, 1, 0), glm::vec3(0, 1, 0)});
    }
    for (uint32_t s = 0; s < segments; ++s) {
        uint32_t a = 2 * s, b = a + 1, c = a + 2, d = a + 3;
        m.indices.insert(m.indices.end(), {a, c, b, b, c, d});
    }
    return m;
}

scene::Light directionalLight(glm::vec3 direction, float lux) {
    scene::Light l;
    l.type = scene::LightType::Directional;
    l.direction = glm::normalize(direction);
    l.intensity = lux;
    return l;
}

void forEachPixelOnPlane(const scene::Camera& camera, uint32_t width, uint32_t height, float planeY,
                         const std::function<void(uint32_t, uint32_t, glm::vec3, float)>& f) {
    namespace sh = caustics::shader;
    sh::PinholeCamera cam = sh::makePinholeCamera(camera.eye, camera.target, camera.up, camera.verticalFovRadians,
                                                  float(width), float(height));
    for (uint32_t y = 0; y < height; ++y) {
        for (uint32_t x = 0; x < width; ++x) {
            glm::vec3 d = sh::cameraRayDirection(cam, glm::vec2(x + 0.5f, y + 0.5f));
            if (std::abs(d.y) < 1e-6f) continue;
            float t = (planeY - cam.eye.y) / d.y;
            if (t <= 0.0f) continue;
            float cosC = glm::dot(d, cam.forward);
            float footprint = sh::pinholePixelArea(cam) * cosC * cosC * cosC * t * t / std::abs(d.y);
            f(x, y, cam.eye + t * d, footprint);
        }
    }
}

}  // namespace caustics::physics
