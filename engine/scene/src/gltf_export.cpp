// Scene -> glTF 2.0 (tinygltf writer): one buffer, one mesh per Mesh, one node per instance (its
// matrix), one node per light (rotation taking -Z to the light direction) and per camera.
#include <algorithm>
#include <cstring>
#include <filesystem>

#include <glm/gtc/matrix_transform.hpp>
#include <glm/gtc/quaternion.hpp>
#include <glm/gtc/type_ptr.hpp>

#include "gltf_internal.h"
#include "caustics/scene/gltf.h"

namespace caustics::scene {

namespace {

class Writer {
public:
    tinygltf::Model model;

    Writer() {
        model.buffers.emplace_back();
        model.asset.version = "2.0";
        model.asset.generator = "caustics::scene::writeGltf";
    }

    int addView(const void* data, size_t bytes, int target) {
        auto& buf = model.buffers[0].data;
        while (buf.size() % 4) buf.push_back(0);   // glTF 2.0 3.6.2.4: accessor data aligned to 4
        tinygltf::BufferView view;
        view.buffer = 0;
        view.byteOffset = buf.size();
        view.byteLength = bytes;
        view.target = target;
        const auto* p = static_cast<const unsigned char*>(data);
        buf.insert(buf.end(), p, p + bytes);
        model.bufferViews.push_back(view);
        return int(model.bufferViews.size() - 1);
    }

    int addAccessor(const void* data, size_t count, int type, int comps, int componentType, int target) {
        size_t bytes = count * size_t(comps) * 4;
        tinygltf::Accessor acc;
        acc.bufferView = addView(data, bytes, target);
        acc.count = count;
        acc.type = type;
        acc.componentType = componentType;
        model.accessors.push_back(acc);
        return int(model.accessors.size() - 1);
    }

    static void encodePng(void* context, void* data, int size) {
        auto* out = static_cast<std::vector<unsigned char>*>(context);
        out->insert(out->end(), static_cast<unsigned char*>(data), static_cast<unsigned char*>(data) + size);
    }
};

tinygltf::Value number(double v) { return tinygltf::Value(v); }
tinygltf::Value vec3Value(const glm::vec3& v) {
    return tinygltf::Value(tinygltf::Value::Array{number(v.x), number(v.y), number(v.z)});
}

tinygltf::Material toGltf(const Material& m) {
    tinygltf::Material g;
    g.name = m.name;
    g.pbrMetallicRoughness.baseColorFactor = {m.baseColor.r, m.baseColor.g, m.baseColor.b, 1.0};
    g.pbrMetallicRoughness.metallicFactor = m.metallic;
    g.pbrMetallicRoughness.roughnessFactor = m.roughness;
    g.pbrMetallicRoughness.baseColorTexture.index = m.baseColorTexture;
    g.doubleSided = m.doubleSided;
    using Obj = tinygltf::Value::Object;
    // emissiveFactor is limited to [0, 1] (the importer clamps it); brighter emission goes through
    // KHR_materials_emissive_strength so that it survives the round trip.
    float strength = std::max({m.emissive.r, m.emissive.g, m.emissive.b});
    glm::vec3 factor = strength > 1.0f ? m.emissive / strength : m.emissive;
    g.emissiveFactor = {factor.r, factor.g, factor.b};
    if (strength > 1.0f) g.extensions["KHR_materials_emissive_strength"] = tinygltf::Value(Obj{{"emissiveStrength", number(strength)}});
    if (m.transmission > 0.0f) g.extensions["KHR_materials_transmission"] = tinygltf::Value(Obj{{"transmissionFactor", number(m.transmission)}});
    g.extensions["KHR_materials_ior"] = tinygltf::Value(Obj{{"ior", number(m.ior)}});
    if (m.thickness > 0.0f || m.attenuationDistance > 0.0f) {
        Obj volume{{"thicknessFactor", number(m.thickness)}, {"attenuationColor", vec3Value(m.attenuationColor)}};
        if (m.attenuationDistance > 0.0f) volume["attenuationDistance"] = number(m.attenuationDistance);
        g.extensions["KHR_materials_volume"] = tinygltf::Value(volume);
    }
    g.extensions["KHR_materials_specular"] =
        tinygltf::Value(Obj{{"specularFactor", number(m.specular)}, {"specularColorFactor", vec3Value(m.specularColor)}});
    return g;
}

// Rotation taking the node's -Z axis to `dir` (lights and cameras look down -Z).
glm::quat lookRotation(const glm::vec3& dir, const glm::vec3& upHint) {
    glm::vec3 f = glm::normalize(dir);
    glm::vec3 up = std::abs(glm::dot(f, glm::normalize(upHint))) > 0.999f ? glm::vec3(1, 0, 0) : upHint;
    glm::vec3 r = glm::normalize(glm::cross(f, up));
    glm::vec3 u = glm::cross(r, f);
    return glm::quat_cast(glm::mat3(r, u, -f));
}

void placeNode(tinygltf::Node& node, const glm::vec3& position, const glm::quat& rotation) {
    node.translation = {position.x, position.y, position.z};
    node.rotation = {rotation.x, rotation.y, rotation.z, rotation.w};
}

}  // namespace

Status writeGltf(const Scene& scene, const std::string& path) {
    try {
        Writer w;
        tinygltf::Model& model = w.model;
        for (const Texture& tex : scene.textures) {
            std::vector<unsigned char> png;
            if (tex.width == 0 || tex.height == 0 || tex.rgba8.size() != size_t(tex.width) * tex.height * 4 ||
                !stbi_write_png_to_func(Writer::encodePng, &png, int(tex.width), int(tex.height), 4, tex.rgba8.data(),
                                        int(tex.width * 4)))
                return makeError(path + ": cannot encode texture '" + tex.name + "' as PNG");
            tinygltf::Image img;
            img.name = tex.name;
            img.mimeType = "image/png";
            img.bufferView = w.addView(png.data(), png.size(), 0);
            model.images.push_back(img);
            tinygltf::Texture t;
            t.source = int(model.images.size() - 1);
            model.textures.push_back(t);
        }
        for (const Material& m : scene.materials) model.materials.push_back(toGltf(m));
        for (const Mesh& mesh : scene.meshes) {
            tinygltf::Primitive prim;
            prim.mode = TINYGLTF_MODE_TRIANGLES;
            prim.material = int(mesh.material);
            int pos = w.addAccessor(mesh.positions.data(), mesh.positions.size(), TINYGLTF_TYPE_VEC3, 3,
                                    TINYGLTF_COMPONENT_TYPE_FLOAT, TINYGLTF_TARGET_ARRAY_BUFFER);
            glm::vec3 lo(0.0f), hi(0.0f);   // glTF 2.0 3.6.2.2: POSITION needs min and max
            if (!mesh.positions.empty()) {
                lo = hi = mesh.positions[0];
                for (const glm::vec3& p : mesh.positions) { lo = glm::min(lo, p); hi = glm::max(hi, p); }
            }
            model.accessors[size_t(pos)].minValues = {lo.x, lo.y, lo.z};
            model.accessors[size_t(pos)].maxValues = {hi.x, hi.y, hi.z};
            prim.attributes["POSITION"] = pos;
            if (mesh.normals.size() == mesh.positions.size())
                prim.attributes["NORMAL"] = w.addAccessor(mesh.normals.data(), mesh.normals.size(), TINYGLTF_TYPE_VEC3, 3,
                                                          TINYGLTF_COMPONENT_TYPE_FLOAT, TINYGLTF_TARGET_ARRAY_BUFFER);
            if (mesh.uvs.size() == mesh.positions.size())
                prim.attributes["TEXCOORD_0"] = w.addAccessor(mesh.uvs.data(), mesh.uvs.size(), TINYGLTF_TYPE_VEC2, 2,
                                                              TINYGLTF_COMPONENT_TYPE_FLOAT, TINYGLTF_TARGET_ARRAY_BUFFER);
            if (mesh.tangents.size() == mesh.positions.size())
                prim.attributes["TANGENT"] = w.addAccessor(mesh.tangents.data(), mesh.tangents.size(), TINYGLTF_TYPE_VEC4, 4,
                                                           TINYGLTF_COMPONENT_TYPE_FLOAT, TINYGLTF_TARGET_ARRAY_BUFFER);
            prim.indices = w.addAccessor(mesh.indices.data(), mesh.indices.size(), TINYGLTF_TYPE_SCALAR, 1,
                                         TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT, TINYGLTF_TARGET_ELEMENT_ARRAY_BUFFER);
            tinygltf::Mesh gm;
            gm.name = mesh.name;
            gm.primitives.push_back(prim);
            model.meshes.push_back(gm);
        }
        tinygltf::Scene root;
        root.name = scene.name;
        for (const Instance& inst : scene.instances) {
            tinygltf::Node node;
            node.mesh = int(inst.mesh);
            const float* m = glm::value_ptr(inst.transform);
            node.matrix.assign(m, m + 16);   // both column-major
            model.nodes.push_back(node);
            root.nodes.push_back(int(model.nodes.size() - 1));
        }
        for (const Light& l : scene.lights) {
            tinygltf::Light gl;
            gl.name = l.name;
            gl.type = l.type == LightType::Point ? "point" : l.type == LightType::Spot ? "spot" : "directional";
            gl.color = {l.color.r, l.color.g, l.color.b};
            gl.intensity = l.intensity;
            gl.range = l.range;
            gl.spot.innerConeAngle = l.innerConeAngle;
            gl.spot.outerConeAngle = l.outerConeAngle;
            model.lights.push_back(gl);
            tinygltf::Node node;
            node.name = l.name;
            placeNode(node, l.position, lookRotation(l.direction, {0, 1, 0}));
            node.extensions["KHR_lights_punctual"] =
                tinygltf::Value(tinygltf::Value::Object{{"light", tinygltf::Value(int(model.lights.size() - 1))}});
            model.nodes.push_back(node);
            root.nodes.push_back(int(model.nodes.size() - 1));
        }
        if (!model.lights.empty()) model.extensionsUsed.push_back("KHR_lights_punctual");
        for (const char* ext : {"KHR_materials_transmission", "KHR_materials_ior", "KHR_materials_volume", "KHR_materials_specular",
                                "KHR_materials_emissive_strength"})
            if (std::any_of(model.materials.begin(), model.materials.end(), [&](const tinygltf::Material& m) { return m.extensions.count(ext) > 0; }))
                model.extensionsUsed.push_back(ext);
        for (const Camera& c : scene.cameras) {
            tinygltf::Camera gc;
            gc.type = "perspective";
            gc.perspective.yfov = c.verticalFovRadians;
            gc.perspective.znear = c.nearPlane;
            gc.perspective.zfar = c.farPlane;
            gc.perspective.aspectRatio = 0.0;   // unspecified: the viewport's aspect
            model.cameras.push_back(gc);
            tinygltf::Node node;
            node.camera = int(model.cameras.size() - 1);
            placeNode(node, c.eye, lookRotation(c.target - c.eye, c.up));
            model.nodes.push_back(node);
            root.nodes.push_back(int(model.nodes.size() - 1));
        }
        model.scenes.push_back(root);
        model.defaultScene = 0;

        std::string ext = std::filesystem::path(path).extension().string();
        std::transform(ext.begin(), ext.end(), ext.begin(), [](unsigned char ch) { return char(std::tolower(ch)); });
        bool binary = ext == ".glb";
        tinygltf::TinyGLTF writer;
        if (!writer.WriteGltfSceneToFile(&model, path, false, true, !binary, binary))
            return makeError(path + ": cannot write the glTF file");
        return okStatus();
    } catch (const std::exception& e) {
        return makeError(path + ": cannot write the glTF file (" + std::string(e.what()) + ")");
    }
}

}  // namespace caustics::scene
