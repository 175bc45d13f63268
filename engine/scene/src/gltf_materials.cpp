// glTF 2.0 materials, lights and cameras -> the scene model. Extensions per the Khronos specs:
// KHR_materials_transmission (transmissionFactor), KHR_materials_ior (ior, default 1.5),
// KHR_materials_volume (thicknessFactor, attenuationDistance, attenuationColor),
// KHR_materials_specular (specularFactor, specularColorFactor), KHR_materials_emissive_strength,
// KHR_lights_punctual (point/spot in candela, directional in lux; the light looks down its -Z).
// Values outside the schema's ranges are clamped with a warning that names the field, the value and
// the range (docs/viewer.md, "Untrusted glTF").
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

static double rawNumber(const tinygltf::Value& object, const char* key, double fallback) {
    const tinygltf::Value* v = member(object, key);
    return (v && v->IsNumber()) ? v->GetNumberAsDouble() : fallback;
}

static std::string number(double v) {
    char text[32];
    std::snprintf(text, sizeof(text), "%.6g", v);
    return text;
}

namespace {

// Collects "field value is outside [lo, hi]; using x" notes for one material or light.
struct Clamper {
    std::string label;                  // "material 0 ('glass')"
    std::vector<std::string>* notes;    // where the warnings go

    // `value` clamped into [lo, hi] (NaN -> fallback); a value outside gets a warning.
    float operator()(const std::string& field, double value, double lo, double hi, float fallback, const char* unit = "") {
        if (!std::isfinite(value) && !std::isnan(value)) value = value > 0 ? hi : lo;   // +-inf: the nearer end
        else if (std::isnan(value)) {
            notes->push_back(label + ": " + field + " is NaN; using " + number(fallback) + unit);
            return fallback;
        }
        if (value >= lo && value <= hi) return float(value);
        double used = std::clamp(value, lo, hi);
        notes->push_back(label + ": " + field + " " + number(value) + unit + " is outside [" + number(lo) + ", " +
                         number(hi) + "]" + unit + "; using " + number(used) + unit);
        return float(used);
    }
};

}  // namespace

Material convertMaterial(const tinygltf::Material& src, size_t index, const std::vector<int>& textureToImage,
                         float maxEmission, std::vector<std::string>& warnings) {
    Material m;
    m.name = src.name;
    Clamper clamp{"material " + std::to_string(index) + (src.name.empty() ? "" : " ('" + shortened(src.name, 64) + "')"),
                  &warnings};
    const auto& pbr = src.pbrMetallicRoughness;
    if (pbr.baseColorFactor.size() >= 3)
        for (int i = 0; i < 3; ++i)
            m.baseColor[i] = clamp("baseColorFactor[" + std::to_string(i) + "]", pbr.baseColorFactor[size_t(i)], 0.0, 1.0, 1.0f);
    m.metallic = clamp("metallicFactor", pbr.metallicFactor, 0.0, 1.0, 1.0f);
    m.roughness = clamp("roughnessFactor", pbr.roughnessFactor, 0.0, 1.0, 1.0f);
    int tex = pbr.baseColorTexture.index;
    if (tex >= 0) {
        if (size_t(tex) < textureToImage.size() && textureToImage[size_t(tex)] >= 0)
            m.baseColorTexture = textureToImage[size_t(tex)];
        else
            warnings.push_back(clamp.label + " refers to texture " + std::to_string(tex) + " that has no image; ignored");
    }
    if (src.emissiveFactor.size() >= 3)
        for (int i = 0; i < 3; ++i)
            m.emissive[i] = clamp("emissiveFactor[" + std::to_string(i) + "]", src.emissiveFactor[size_t(i)], 0.0, 1.0, 0.0f);
    m.doubleSided = src.doubleSided;

    if (const tinygltf::Value* e = extension(src.extensions, "KHR_materials_transmission"))
        m.transmission = clamp("KHR_materials_transmission.transmissionFactor", rawNumber(*e, "transmissionFactor", 0.0),
                               0.0, 1.0, 0.0f);
    if (const tinygltf::Value* e = extension(src.extensions, "KHR_materials_ior"))
        // Schema minimum 1 (a vacuum); an IOR of 0 or below would make refraction undefined.
        m.ior = clamp("KHR_materials_ior.ior", rawNumber(*e, "ior", 1.5), 1.0, 1e3, 1.5f);
    if (const tinygltf::Value* e = extension(src.extensions, "KHR_materials_volume")) {
        m.thickness = clamp("KHR_materials_volume.thicknessFactor", rawNumber(*e, "thicknessFactor", 0.0), 0.0, 1e6, 0.0f);
        m.attenuationDistance = std::max(numberOr(*e, "attenuationDistance", 0.0f), 0.0f);
        m.attenuationColor = glm::clamp(vec3Or(*e, "attenuationColor", glm::vec3(1.0f)), 0.0f, 1.0f);
    }
    if (const tinygltf::Value* e = extension(src.extensions, "KHR_materials_specular")) {
        m.specular = clamp("KHR_materials_specular.specularFactor", rawNumber(*e, "specularFactor", 1.0), 0.0, 1.0, 1.0f);
        m.specularColor = glm::max(vec3Or(*e, "specularColorFactor", glm::vec3(1.0f)), 0.0f);
    }
    if (const tinygltf::Value* e = extension(src.extensions, "KHR_materials_emissive_strength"))
        m.emissive *= clamp("KHR_materials_emissive_strength.emissiveStrength", rawNumber(*e, "emissiveStrength", 1.0), 0.0,
                            double(maxEmission), 1.0f, "");
    float brightest = std::max({m.emissive.r, m.emissive.g, m.emissive.b});
    if (brightest > maxEmission) m.emissive *= maxEmission / brightest;
    return m;
}

static bool finite(const glm::vec3& v) { return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z); }

bool convertLight(const tinygltf::Light& src, const glm::mat4& world, float maxIntensity, Light& out,
                  std::string& problem, std::string& warning) {
    out = Light{};
    out.name = src.name;
    if (src.type == "point") out.type = LightType::Point;
    else if (src.type == "spot") out.type = LightType::Spot;
    else if (src.type == "directional") out.type = LightType::Directional;
    else {
        problem = "has unknown type '" + shortened(src.type, 32) + "'";
        return false;
    }
    std::vector<std::string> notes;
    Clamper clamp{"", &notes};
    const char* unit = out.type == LightType::Directional ? " lux" : " cd";
    if (src.color.size() >= 3)   // KHR_lights_punctual: colour components in [0, 1]
        for (int i = 0; i < 3; ++i) out.color[i] = clamp("color[" + std::to_string(i) + "]", src.color[size_t(i)], 0.0, 1.0, 1.0f);
    // The intensity is >= 0 (the importer refuses a negative one); the limit keeps radiance finite.
    out.intensity = clamp("intensity", src.intensity, 0.0, double(maxIntensity), 1.0f, unit);
    if (src.range > 0.0 || src.range < 0.0) out.range = clamp("range", src.range, 0.0, 1e30, 0.0f, " m");
    if (out.type == LightType::Spot) {
        out.innerConeAngle = clamp("spot.innerConeAngle", src.spot.innerConeAngle, 0.0, 1.5707963, 0.0f, " rad");
        out.outerConeAngle = clamp("spot.outerConeAngle", src.spot.outerConeAngle, 0.0, 1.5707963, 0.785398f, " rad");
    } else {
        out.innerConeAngle = 0.0f;
        out.outerConeAngle = 0.785398f;
    }
    if (out.type == LightType::Spot && out.innerConeAngle >= out.outerConeAngle) {
        // glTF 2.0 KHR_lights_punctual requires inner < outer; the falloff (cosInner - cosOuter) would
        // be empty. A hard-edged cone (inner = outer) is the nearest meaning; say so.
        char text[160];
        std::snprintf(text, sizeof(text), "spot cone: innerConeAngle %.3g rad is not below outerConeAngle %.3g rad; "
                      "using a hard-edged cone of %.3g rad", double(out.innerConeAngle), double(out.outerConeAngle),
                      double(out.outerConeAngle));
        notes.push_back(text);
    }
    out.innerConeAngle = std::min(out.innerConeAngle, out.outerConeAngle);
    for (std::string& n : notes) {
        if (n.rfind(": ", 0) == 0) n.erase(0, 2);   // the Clamper's empty label
        warning += (warning.empty() ? "" : "; ") + n;
    }
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
