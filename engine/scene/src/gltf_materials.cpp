// glTF 2.0 materials, lights and cameras -> the scene model. Extensions per the Khronos specs:
// KHR_materials_transmission (transmissionFactor), KHR_materials_ior (ior, default 1.5),
// KHR_materials_volume (thicknessFactor, attenuationDistance, attenuationColor),
// KHR_materials_specular (specularFactor, specularColorFactor), KHR_materials_emissive_strength,
// KHR_lights_punctual (point/spot in candela, directional in lux; the light looks down its -Z).
#include <algorithm>
#include <cmath>
#include <cstdio>

#include "gltf_internal.h"

namespace caustics::scene::gltf {

static float finiteOr(double v, float fallback) { return std::isfinite(v) ? float(v) : fallback; }

static const tinygltf::Value* extension(const tinygltf::ExtensionMap& map, const char* name) {
    auto it = map.find(name);
    return (it != map.end() && it->second.IsObject()) ? &it->second : nullptr;
}

Material convertMaterial(const tinygltf::Material& src, const std::vector<int>& textureToImage,
                         std::vector<std::string>& warnings) {
    Material m;
    m.name = src.name;
    const auto& pbr = src.pbrMetallicRoughness;
    if (pbr.baseColorFactor.size() >= 3)
        for (int i = 0; i < 3; ++i) m.baseColor[i] = std::clamp(finiteOr(pbr.baseColorFactor[size_t(i)], 1.0f), 0.0f, 1.0f);
    m.metallic = std::clamp(finiteOr(pbr.metallicFactor, 1.0f), 0.0f, 1.0f);
    m.roughness = std::clamp(finiteOr(pbr.roughnessFactor, 1.0f), 0.0f, 1.0f);
    int tex = pbr.baseColorTexture.index;
    if (tex >= 0) {
        if (size_t(tex) < textureToImage.size() && textureToImage[size_t(tex)] >= 0)
            m.baseColorTexture = textureToImage[size_t(tex)];
        else
            warnings.push_back("material '" + src.name + "' refers to texture " + std::to_string(tex) +
                               " that has no image; ignored");
    }
    if (src.emissiveFactor.size() >= 3)
        for (int i = 0; i < 3; ++i) m.emissive[i] = std::max(finiteOr(src.emissiveFactor[size_t(i)], 0.0f), 0.0f);
    m.doubleSided = src.doubleSided;

    if (const tinygltf::Value* e = extension(src.extensions, "KHR_materials_transmission"))
        m.transmission = std::clamp(numberOr(*e, "transmissionFactor", 0.0f), 0.0f, 1.0f);
    if (const tinygltf::Value* e = extension(src.extensions, "KHR_materials_ior")) {
        m.ior = numberOr(*e, "ior", 1.5f);
        // The spec allows 0 (a pure-reflective "infinite" IOR); otherwise ior >= 1.
        if (m.ior != 0.0f && m.ior < 1.0f) m.ior = 1.0f;
    }
    if (const tinygltf::Value* e = extension(src.extensions, "KHR_materials_volume")) {
        m.thickness = std::max(numberOr(*e, "thicknessFactor", 0.0f), 0.0f);
        m.attenuationDistance = std::max(numberOr(*e, "attenuationDistance", 0.0f), 0.0f);
        m.attenuationColor = glm::clamp(vec3Or(*e, "attenuationColor", glm::vec3(1.0f)), 0.0f, 1.0f);
    }
    if (const tinygltf::Value* e = extension(src.extensions, "KHR_materials_specular")) {
        m.specular = std::clamp(numberOr(*e, "specularFactor", 1.0f), 0.0f, 1.0f);
        m.specularColor = glm::max(vec3Or(*e, "specularColorFactor", glm::vec3(1.0f)), 0.0f);
    }
    if (const tinygltf::Value* e = extension(src.extensions, "KHR_materials_emissive_strength"))
        m.emissive *= std::max(numberOr(*e, "emissiveStrength", 1.0f), 0.0f);
    return m;
}

static bool finite(const glm::vec3& v) { return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z); }

bool convertLight(const tinygltf::Light& src, const glm::mat4& world, Light& out, std::string& problem,
                  std::string& warning) {
    out = Light{};
    out.name = src.name;
    if (src.type == "point") out.type = LightType::Point;
    else if (src.type == "spot") out.type = LightType::Spot;
    else if (src.type == "directional") out.type = LightType::Directional;
    else {
        problem = "has unknown type '" + src.type + "'";
        return false;
    }
    if (src.color.size() >= 3)
        for (int i = 0; i < 3; ++i) out.color[i] = std::max(finiteOr(src.color[size_t(i)], 1.0f), 0.0f);
    out.intensity = finiteOr(src.intensity, -1.0f);
    if (out.intensity < 0.0f) {
        problem = "has an invalid intensity";
        return false;
    }
    out.range = std::max(finiteOr(src.range, 0.0f), 0.0f);
    out.innerConeAngle = std::max(finiteOr(src.spot.innerConeAngle, 0.0f), 0.0f);
    out.outerConeAngle = std::clamp(finiteOr(src.spot.outerConeAngle, 0.785398f), 0.0f, 1.5707963f);
    if (out.type == LightType::Spot && out.innerConeAngle >= out.outerConeAngle) {
        // glTF 2.0 KHR_lights_punctual requires inner < outer; the falloff (cosInner - cosOuter) would
        // be empty. A hard-edged cone (inner = outer) is the nearest meaning; say so.
        char text[160];
        std::snprintf(text, sizeof(text), "spot cone: innerConeAngle %.3g rad is not below outerConeAngle %.3g rad; "
                      "using a hard-edged cone of %.3g rad", double(out.innerConeAngle), double(out.outerConeAngle),
                      double(out.outerConeAngle));
        warning = text;
    }
    out.innerConeAngle = std::min(out.innerConeAngle, out.outerConeAngle);
    out.position = glm::vec3(world * glm::vec4(0.0f, 0.0f, 0.0f, 1.0f));
    glm::vec3 dir = glm::vec3(world * glm::vec4(0.0f, 0.0f, -1.0f, 0.0f));
    float len = glm::length(dir);
    if (!finite(out.position) || !(len > 0.0f) || !std::isfinite(len)) {
        problem = "is placed by a degenerate node transform";
        return false;
    }
    out.direction = dir / len;
    return true;
}

bool convertCamera(const tinygltf::Camera& src, const glm::mat4& world, Camera& out, std::string& problem) {
    if (src.type != "perspective") {
        problem = "is of type '" + src.type + "'; only perspective cameras are imported";
        return false;
    }
    out = Camera{};
    float yfov = finiteOr(src.perspective.yfov, 0.0f);
    if (!(yfov > 0.0f && yfov < 3.14159f)) {
        problem = "has an invalid yfov";
        return false;
    }
    out.verticalFovRadians = yfov;
    float znear = finiteOr(src.perspective.znear, 0.0f);
    if (znear > 0.0f) out.nearPlane = znear;
    float zfar = finiteOr(src.perspective.zfar, 0.0f);   // 0 = infinite projection: keep the default
    if (zfar > out.nearPlane) out.farPlane = zfar;
    out.eye = glm::vec3(world * glm::vec4(0.0f, 0.0f, 0.0f, 1.0f));
    glm::vec3 forward = glm::vec3(world * glm::vec4(0.0f, 0.0f, -1.0f, 0.0f));
    glm::vec3 up = glm::vec3(world * glm::vec4(0.0f, 1.0f, 0.0f, 0.0f));
    if (!finite(out.eye) || !(glm::length(forward) > 0.0f) || !(glm::length(up) > 0.0f) || !finite(forward)) {
        problem = "is placed by a degenerate node transform";
        return false;
    }
    out.target = out.eye + glm::normalize(forward);
    out.up = glm::normalize(up);
    return true;
}

}  // namespace caustics::scene::gltf
