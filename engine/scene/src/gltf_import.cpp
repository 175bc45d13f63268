// glTF 2.0 import: file -> tinygltf::Model (inside a catch-all boundary) -> checked conversion.
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <fstream>

#include <glm/gtc/quaternion.hpp>
#include <glm/gtc/type_ptr.hpp>

#include "gltf_internal.h"
#include "caustics/rhi/log.h"
#include "caustics/scene/gltf.h"
#include "caustics/scene/mesh_utils.h"
#include "caustics/scene/procedural_textures.h"

namespace caustics::scene {

using namespace gltf;

namespace {

struct ImageContext {
    const LoadOptions* options = nullptr;
    std::string error;
};

// tinygltf image callback: decode to RGBA8 via stb_image, refusing images beyond the size limit
// before decoding them. A corrupt image is a warning (it becomes 1x1 white later), not an error.
bool decodeImage(tinygltf::Image* image, const int index, std::string* err, std::string* warn, int, int,
                 const unsigned char* bytes, int size, void* user) {
    auto* ctx = static_cast<ImageContext*>(user);
    if (!ctx->options->loadImages) return true;
    int w = 0, h = 0, comps = 0;
    if (!stbi_info_from_memory(bytes, size, &w, &h, &comps)) {
        if (warn) *warn += "image " + std::to_string(index) + " cannot be decoded (" + stbi_failure_reason() + ")\n";
        return true;
    }
    uint32_t limit = ctx->options->maxTextureDimension;
    if (uint32_t(w) > limit || uint32_t(h) > limit) {
        ctx->error = "image " + std::to_string(index) + " is " + std::to_string(w) + "x" + std::to_string(h) +
                     ", larger than the limit LoadOptions::maxTextureDimension = " + std::to_string(limit);
        if (err) *err += ctx->error;
        return false;
    }
    unsigned char* pixels = stbi_load_from_memory(bytes, size, &w, &h, &comps, 4);
    if (!pixels) {
        if (warn) *warn += "image " + std::to_string(index) + " cannot be decoded (" + stbi_failure_reason() + ")\n";
        return true;
    }
    image->width = w;
    image->height = h;
    image->component = 4;
    image->bits = 8;
    image->pixel_type = TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE;
    image->image.assign(pixels, pixels + size_t(w) * size_t(h) * 4);
    stbi_image_free(pixels);
    return true;
}

std::string trimmed(std::string s) {
    while (!s.empty() && (s.back() == '\n' || s.back() == ' ')) s.pop_back();
    return s;
}

void logLines(const std::string& path, const std::string& text) {
    size_t start = 0;
    while (start < text.size()) {
        size_t end = text.find('\n', start);
        if (end == std::string::npos) end = text.size();
        if (end > start) log(LogLevel::Warning, path + ": " + text.substr(start, end - start));
        start = end + 1;
    }
}

bool finiteVec(const glm::vec3& v) { return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z); }

std::string nodeLabel(const tinygltf::Node& node, size_t index) {
    return "node " + std::to_string(index) + (node.name.empty() ? "" : " ('" + shortened(node.name, 64) + "')");
}

// Largest factor by which the upper 3x3 stretches a unit vector's axis (column norms).
// Computed in double: a 1e30 scale squared overflows float.
double maxAxisScale(const glm::mat4& m) {
    double largest = 0.0;
    for (int c = 0; c < 3; ++c)
        largest = std::max(largest, std::sqrt(double(m[c][0]) * m[c][0] + double(m[c][1]) * m[c][1] + double(m[c][2]) * m[c][2]));
    return largest;
}

// Beyond this a mesh of metre-sized features spans more than 1000 km: ray-triangle tests in float
// lose all precision (the ray epsilon alone exceeds the objects in view), so the instance would vanish.
constexpr double kMaxInstanceScale = 1e6;

Result<glm::mat4> localTransform(const tinygltf::Node& node, size_t index) {
    glm::mat4 m(1.0f);
    std::string name = "node " + std::to_string(index);
    if (!node.matrix.empty()) {
        if (node.matrix.size() != 16) return makeError(name + " has a matrix of " + std::to_string(node.matrix.size()) + " numbers, expected 16");
        for (int i = 0; i < 16; ++i) glm::value_ptr(m)[i] = float(node.matrix[size_t(i)]);   // column-major, as glTF
    } else {
        glm::vec3 t(0.0f), s(1.0f);
        glm::quat r(1.0f, 0.0f, 0.0f, 0.0f);
        if (node.translation.size() == 3) t = {float(node.translation[0]), float(node.translation[1]), float(node.translation[2])};
        if (node.scale.size() == 3) s = {float(node.scale[0]), float(node.scale[1]), float(node.scale[2])};
        if (node.rotation.size() == 4)   // glTF stores (x, y, z, w)
            r = glm::quat(float(node.rotation[3]), float(node.rotation[0]), float(node.rotation[1]), float(node.rotation[2]));
        m = glm::translate(glm::mat4(1.0f), t) * glm::mat4_cast(r) * glm::scale(glm::mat4(1.0f), s);
    }
    for (int i = 0; i < 16; ++i)
        if (!std::isfinite(glm::value_ptr(m)[i])) return makeError(name + " has a non-finite transform");
    return m;
}

class Importer {
public:
    Importer(const tinygltf::Model& model, const LoadOptions& options) : model_(model), options_(options) {}
    Status run(Scene& scene);
    std::vector<std::string> warnings;

private:
    Status convertMeshes(Scene& scene);
    Result<Mesh> convertPrimitive(const tinygltf::Primitive& prim, size_t meshIndex, size_t primIndex);
    Status convertNodes(Scene& scene);
    uint32_t defaultMaterial(Scene& scene);

    const tinygltf::Model& model_;
    const LoadOptions& options_;
    std::vector<std::vector<uint32_t>> meshPrimitives_;   // glTF mesh -> scene meshes
    uint64_t triangles_ = 0, vertices_ = 0;
    int defaultMaterial_ = -1;
    uint32_t skippedInstances_ = 0;
};

Status Importer::run(Scene& scene) {
    for (const std::string& ext : model_.extensionsRequired)
        if (!isSupportedExtension(ext)) return makeError("requires the unsupported extension '" + shortened(ext, 64) + "'");
    if (model_.meshes.empty()) return makeError("contains no meshes");

    for (size_t i = 0; i < model_.images.size(); ++i) {
        const tinygltf::Image& img = model_.images[i];
        Texture tex;
        tex.name = img.name.empty() ? img.uri : img.name;
        if (img.image.empty() || img.width <= 0 || img.height <= 0 ||
            img.image.size() != size_t(img.width) * size_t(img.height) * 4) {
            if (options_.loadImages)
                warnings.push_back("image " + std::to_string(i) + " ('" + tex.name +
                                   "') could not be loaded; using a 1x1 white texture");
            tex = makeSolidTexture(glm::vec3(1.0f), tex.name);
        } else {
            tex.width = uint32_t(img.width);
            tex.height = uint32_t(img.height);
            tex.rgba8 = img.image;
        }
        scene.textures.push_back(std::move(tex));
    }
    std::vector<int> textureToImage;
    for (const tinygltf::Texture& t : model_.textures)
        textureToImage.push_back(t.source >= 0 && size_t(t.source) < model_.images.size() ? t.source : -1);
    for (const tinygltf::Material& mat : model_.materials)
        scene.materials.push_back(convertMaterial(mat, textureToImage, warnings));

    CAUSTICS_CHECK(convertMeshes(scene));
    CAUSTICS_CHECK(convertNodes(scene));
    return okStatus();
}

uint32_t Importer::defaultMaterial(Scene& scene) {
    if (defaultMaterial_ < 0) {
        defaultMaterial_ = int(scene.materials.size());
        Material m;
        m.name = "default";
        m.metallic = 1.0f;   // glTF 2.0 3.9.6: the default material is metallic 1, roughness 1
        scene.materials.push_back(m);
    }
    return uint32_t(defaultMaterial_);
}

Status Importer::convertMeshes(Scene& scene) {
    meshPrimitives_.resize(model_.meshes.size());
    for (size_t m = 0; m < model_.meshes.size(); ++m) {
        const tinygltf::Mesh& gm = model_.meshes[m];
        for (size_t p = 0; p < gm.primitives.size(); ++p) {
            const tinygltf::Primitive& prim = gm.primitives[p];
            if (prim.mode != TINYGLTF_MODE_TRIANGLES) {
                warnings.push_back("mesh " + std::to_string(m) + " primitive " + std::to_string(p) + " has mode " +
                                   std::to_string(prim.mode) + "; only TRIANGLES (4) is imported, skipped");
                continue;
            }
            CAUSTICS_TRY(Mesh mesh, convertPrimitive(prim, m, p));
            if (prim.material >= 0 && size_t(prim.material) >= model_.materials.size())
                return makeError("mesh " + std::to_string(m) + " primitive " + std::to_string(p) + " refers to material " +
                                 std::to_string(prim.material) + ", but the file has " +
                                 std::to_string(model_.materials.size()) + " materials");
            mesh.material = prim.material >= 0 ? uint32_t(prim.material) : defaultMaterial(scene);
            meshPrimitives_[m].push_back(uint32_t(scene.meshes.size()));
            scene.meshes.push_back(std::move(mesh));
        }
    }
    if (scene.meshes.empty()) return makeError("contains no triangle primitives");
    return okStatus();
}

Result<Mesh> Importer::convertPrimitive(const tinygltf::Primitive& prim, size_t m, size_t p) {
    std::string where = "mesh " + std::to_string(m) + " primitive " + std::to_string(p);
    auto attribute = [&](const char* name) { auto it = prim.attributes.find(name); return it == prim.attributes.end() ? -1 : it->second; };
    int posIndex = attribute("POSITION");
    if (posIndex < 0) return makeError(where + " has no POSITION attribute");
    uint64_t vertexBudget = options_.maxVertices - std::min(options_.maxVertices, vertices_);
    CAUSTICS_TRY(AccessorView pos, viewAccessor(model_, posIndex, "POSITION of " + where, vertexBudget + 1));
    if (pos.components != 3 || model_.accessors[size_t(posIndex)].type != TINYGLTF_TYPE_VEC3 ||
        pos.componentType != TINYGLTF_COMPONENT_TYPE_FLOAT)
        return makeError("POSITION accessor " + std::to_string(posIndex) + " of " + where + " is " +
                         typeName(model_.accessors[size_t(posIndex)].type) + "/" + componentTypeName(pos.componentType) +
                         "; glTF requires VEC3/FLOAT");
    vertices_ += pos.count;
    if (vertices_ > options_.maxVertices)
        return makeError("has more than " + std::to_string(options_.maxVertices) +
                         " vertices, the limit LoadOptions::maxVertices");
    Mesh mesh;
    mesh.name = model_.meshes[m].name.empty() ? where : model_.meshes[m].name + "/" + std::to_string(p);
    mesh.positions.resize(pos.count);
    for (size_t i = 0; i < pos.count; ++i) {
        glm::vec3 v{readFloat(pos, i, 0), readFloat(pos, i, 1), readFloat(pos, i, 2)};
        if (!finiteVec(v)) return makeError("POSITION of " + where + " has a non-finite value (NaN or inf) at vertex " + std::to_string(i));
        mesh.positions[i] = v;
    }

    if (prim.indices >= 0) {
        uint64_t triBudget = options_.maxTriangles - std::min(options_.maxTriangles, triangles_);
        CAUSTICS_TRY(AccessorView idx, viewAccessor(model_, prim.indices, "indices of " + where, 3 * triBudget + 3));
        int type = model_.accessors[size_t(prim.indices)].type;
        if (type != TINYGLTF_TYPE_SCALAR || (idx.componentType != TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE &&
                                             idx.componentType != TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT &&
                                             idx.componentType != TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT))
            return makeError("indices accessor " + std::to_string(prim.indices) + " of " + where + " is " + typeName(type) +
                             "/" + componentTypeName(idx.componentType) +
                             "; glTF requires SCALAR/UNSIGNED_BYTE, UNSIGNED_SHORT or UNSIGNED_INT");
        mesh.indices.resize(idx.count);
        for (size_t i = 0; i < idx.count; ++i) {
            uint32_t v = readIndex(idx, i);
            if (v >= pos.count)
                return makeError("indices of " + where + ": index " + std::to_string(v) + " at position " + std::to_string(i) +
                                 " is out of range of the " + std::to_string(pos.count) + " vertices");
            mesh.indices[i] = v;
        }
    } else {
        mesh.indices.resize(pos.count);
        for (size_t i = 0; i < pos.count; ++i) mesh.indices[i] = uint32_t(i);
    }
    if (mesh.indices.size() % 3 != 0) {
        warnings.push_back(where + " has " + std::to_string(mesh.indices.size()) + " indices, not a multiple of 3; the rest is dropped");
        mesh.indices.resize(mesh.indices.size() / 3 * 3);
    }
    triangles_ += mesh.indices.size() / 3;
    if (triangles_ > options_.maxTriangles)
        return makeError("has more than " + std::to_string(options_.maxTriangles) +
                         " triangles, the limit LoadOptions::maxTriangles");

    // Optional attributes: a wrong count or type is a warning and the attribute is dropped.
    auto optional = [&](const char* name, int comps, auto store) {
        int index = attribute(name);
        if (index < 0) return;
        auto view = viewAccessor(model_, index, std::string(name) + " of " + where, pos.count);
        if (!view) { warnings.push_back(view.message() + "; attribute ignored"); return; }
        if (view->count != pos.count || view->components != comps ||
            (comps == 3 && view->componentType != TINYGLTF_COMPONENT_TYPE_FLOAT)) {
            warnings.push_back(std::string(name) + " of " + where + " does not match POSITION; attribute ignored");
            return;
        }
        store(*view);
    };
    optional("NORMAL", 3, [&](const AccessorView& v) {
        mesh.normals.resize(v.count);
        for (size_t i = 0; i < v.count; ++i) {
            glm::vec3 n{readFloat(v, i, 0), readFloat(v, i, 1), readFloat(v, i, 2)};
            float len = glm::length(n);
            mesh.normals[i] = (std::isfinite(len) && len > 0.0f) ? n / len : glm::vec3(0.0f, 1.0f, 0.0f);
        }
    });
    optional("TEXCOORD_0", 2, [&](const AccessorView& v) {
        mesh.uvs.resize(v.count);
        for (size_t i = 0; i < v.count; ++i) {
            glm::vec2 uv{readFloat(v, i, 0), readFloat(v, i, 1)};
            mesh.uvs[i] = (std::isfinite(uv.x) && std::isfinite(uv.y)) ? uv : glm::vec2(0.0f);
        }
    });
    optional("TANGENT", 4, [&](const AccessorView& v) {
        mesh.tangents.resize(v.count);
        for (size_t i = 0; i < v.count; ++i) mesh.tangents[i] = {readFloat(v, i, 0), readFloat(v, i, 1), readFloat(v, i, 2), readFloat(v, i, 3)};
    });
    if (mesh.normals.empty()) generateNormals(mesh, options_.smoothGeneratedNormals);
    if (options_.sortTriangles) sortTrianglesMorton(mesh);
    return mesh;
}

Status Importer::convertNodes(Scene& scene) {
    std::vector<int> roots;
    int sceneIndex = model_.defaultScene >= 0 ? model_.defaultScene : (model_.scenes.empty() ? -1 : 0);
    if (sceneIndex >= 0 && size_t(sceneIndex) >= model_.scenes.size())
        return makeError("default scene " + std::to_string(sceneIndex) + " does not exist");
    if (sceneIndex >= 0) {
        roots = model_.scenes[size_t(sceneIndex)].nodes;
    } else {   // no scenes: every node that is nobody's child is a root
        std::vector<bool> isChild(model_.nodes.size(), false);
        for (const tinygltf::Node& n : model_.nodes)
            for (int c : n.children) if (c >= 0 && size_t(c) < isChild.size()) isChild[size_t(c)] = true;
        for (size_t i = 0; i < model_.nodes.size(); ++i) if (!isChild[i]) roots.push_back(int(i));
    }
    if (model_.nodes.size() > options_.maxNodes)
        return makeError("has " + std::to_string(model_.nodes.size()) + " nodes, more than the limit LoadOptions::maxNodes = " +
                         std::to_string(options_.maxNodes));
    std::vector<bool> visited(model_.nodes.size(), false);
    std::vector<std::pair<int, glm::mat4>> stack;
    for (auto it = roots.rbegin(); it != roots.rend(); ++it) stack.push_back({*it, glm::mat4(1.0f)});
    while (!stack.empty()) {
        auto [index, parent] = stack.back();
        stack.pop_back();
        if (index < 0 || size_t(index) >= model_.nodes.size())
            return makeError("refers to node " + std::to_string(index) + ", but the file has " + std::to_string(model_.nodes.size()) + " nodes");
        // glTF 2.0 3.5.3: nodes form disjoint strict trees; a second visit is a cycle or a shared node.
        if (visited[size_t(index)]) return makeError("node " + std::to_string(index) + " appears twice in the node hierarchy (a cycle or a shared child)");
        visited[size_t(index)] = true;
        const tinygltf::Node& node = model_.nodes[size_t(index)];
        CAUSTICS_TRY(glm::mat4 local, localTransform(node, size_t(index)));
        glm::mat4 world = parent * local;
        for (int i = 0; i < 16; ++i)
            if (!std::isfinite(glm::value_ptr(world)[i]))
                return makeError(nodeLabel(node, size_t(index)) + " has a non-finite world transform (the scales and "
                                 "translations of it and its parents multiply past the float range)");
        bool hugeScale = node.mesh >= 0 && maxAxisScale(world) > kMaxInstanceScale;
        if (hugeScale) {
            char scale[32];
            std::snprintf(scale, sizeof(scale), "%.3g", maxAxisScale(world));
            warnings.push_back(nodeLabel(node, size_t(index)) + " scales its mesh by " + scale + " (more than " +
                               "1e6): float ray tracing cannot represent it; the instance is skipped");
            ++skippedInstances_;
        }
        if (node.mesh >= 0 && !hugeScale) {
            if (size_t(node.mesh) >= model_.meshes.size())
                return makeError("node " + std::to_string(index) + " refers to mesh " + std::to_string(node.mesh) + ", but the file has " +
                                 std::to_string(model_.meshes.size()) + " meshes");
            for (uint32_t sm : meshPrimitives_[size_t(node.mesh)]) {
                if (scene.instances.size() >= options_.maxInstances)
                    return makeError("has more than " + std::to_string(options_.maxInstances) + " instances, the limit LoadOptions::maxInstances");
                scene.instances.push_back({sm, world, uint32_t(scene.instances.size() + 1)});
            }
        }
        if (node.camera >= 0) {
            if (size_t(node.camera) >= model_.cameras.size())
                return makeError("node " + std::to_string(index) + " refers to camera " + std::to_string(node.camera) + ", but the file has " +
                                 std::to_string(model_.cameras.size()) + " cameras");
            Camera cam;
            std::string problem;
            if (convertCamera(model_.cameras[size_t(node.camera)], world, cam, problem)) scene.cameras.push_back(cam);
            else warnings.push_back("camera " + std::to_string(node.camera) + " " + problem + "; skipped");
        }
        auto ext = node.extensions.find("KHR_lights_punctual");
        if (ext != node.extensions.end()) {
            int light = intOr(ext->second, "light", -1);
            if (light < 0 || size_t(light) >= model_.lights.size())
                return makeError("node " + std::to_string(index) + " refers to light " + std::to_string(light) + ", but the file has " +
                                 std::to_string(model_.lights.size()) + " lights");
            Light out;
            std::string problem, repaired;
            std::string label = "light " + std::to_string(light) +
                                (model_.lights[size_t(light)].name.empty() ? "" : " ('" + shortened(model_.lights[size_t(light)].name, 64) + "')");
            if (convertLight(model_.lights[size_t(light)], world, out, problem, repaired)) scene.lights.push_back(out);
            else warnings.push_back(label + " " + problem + "; skipped");
            if (!repaired.empty()) warnings.push_back(label + ": " + repaired);
        }
        for (auto it = node.children.rbegin(); it != node.children.rend(); ++it) stack.push_back({*it, world});
    }
    if (scene.instances.empty() && skippedInstances_ > 0)
        return makeError("every mesh instance was skipped (" + std::to_string(skippedInstances_) + "; see the warnings)");
    if (scene.instances.empty()) {
        // Meshes no scene uses: show each once at the origin rather than render nothing.
        warnings.push_back("no node instantiates a mesh; every mesh is placed once at the origin");
        for (uint32_t m = 0; m < scene.meshes.size(); ++m) scene.instances.push_back({m, glm::mat4(1.0f), m + 1});
    }
    return okStatus();
}

Result<std::vector<unsigned char>> readFile(const std::string& path) {
    std::error_code ec;
    if (!std::filesystem::exists(path, ec)) return makeError("file not found");
    if (std::filesystem::is_directory(path, ec)) return makeError("is a directory, not a glTF file");
    std::ifstream in(path, std::ios::binary);
    if (!in) return makeError("cannot open the file for reading");
    std::vector<unsigned char> bytes((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
    if (in.bad()) return makeError("cannot read the file");
    if (bytes.empty()) return makeError("the file is empty");
    return bytes;
}

// tinygltf converts "extras"/"extensions" to tinygltf::Value recursively: a hostile file nested
// thousands deep would overflow the stack. Refuse such nesting before parsing.
constexpr int kMaxJsonDepth = 256;
bool jsonTooDeep(const unsigned char* p, size_t n) {
    int depth = 0;
    bool inString = false;
    for (size_t i = 0; i < n; ++i) {
        unsigned char c = p[i];
        if (inString) {
            if (c == '\\') ++i;
            else if (c == '"') inString = false;
        } else if (c == '"') {
            inString = true;
        } else if (c == '[' || c == '{') {
            if (++depth > kMaxJsonDepth) return true;
        } else if (c == ']' || c == '}') {
            --depth;
        }
    }
    return false;
}

Result<Scene> loadUnguarded(const std::string& path, const LoadOptions& options) {
    CAUSTICS_TRY(std::vector<unsigned char> bytes, readFile(path));
    std::filesystem::path fsPath(path);
    std::string ext = fsPath.extension().string();
    std::transform(ext.begin(), ext.end(), ext.begin(), [](unsigned char c) { return char(std::tolower(c)); });
    bool binary = ext == ".glb" || (ext != ".gltf" && bytes.size() >= 4 && std::memcmp(bytes.data(), "glTF", 4) == 0);
    if (binary && (bytes.size() < 4 || std::memcmp(bytes.data(), "glTF", 4) != 0))
        return makeError("is not a binary glTF file (no 'glTF' magic at the start)");
    if (bytes.size() > 0xFFFFFFFFull) return makeError("is larger than 4 GiB");
    size_t jsonBegin = binary ? 20 : 0, jsonLength = bytes.size();
    if (binary && bytes.size() >= 20) {   // GLB: 12-byte header, then the JSON chunk's length and type
        uint32_t chunk = 0;
        std::memcpy(&chunk, bytes.data() + 12, 4);
        jsonLength = std::min<size_t>(chunk, bytes.size() - 20);
    }
    if (binary) CAUSTICS_CHECK(preflightGlb(bytes));
    if (jsonBegin <= bytes.size()) {
        size_t available = std::min(jsonLength, bytes.size() - jsonBegin);
        if (jsonTooDeep(bytes.data() + jsonBegin, available))
            return makeError("invalid JSON: nesting deeper than " + std::to_string(kMaxJsonDepth) + " levels");
        CAUSTICS_CHECK(preflightJson(bytes.data() + jsonBegin, available));
    }

    tinygltf::TinyGLTF loader;
    ImageContext imageContext{&options, {}};
    loader.SetImageLoader(decodeImage, &imageContext);
    tinygltf::Model model;
    std::string err, warn;
    std::string baseDir = fsPath.parent_path().string();
    bool ok = binary ? loader.LoadBinaryFromMemory(&model, &err, &warn, bytes.data(), unsigned(bytes.size()), baseDir)
                     : loader.LoadASCIIFromString(&model, &err, &warn, reinterpret_cast<const char*>(bytes.data()),
                                                  unsigned(bytes.size()), baseDir);
    logLines(path, shortenLongWords(warn));
    if (!imageContext.error.empty()) return makeError(imageContext.error);
    if (!ok) return makeError(err.empty() ? std::string("tinygltf could not parse the file") : shortenLongWords(trimmed(err)));

    Scene scene;
    scene.name = fsPath.stem().string();
    Importer importer(model, options);
    Status status = importer.run(scene);
    for (const std::string& w : importer.warnings) log(LogLevel::Warning, path + ": " + w);
    if (!status) return status.error();
    return scene;
}

}  // namespace

Result<Scene> loadGltf(const std::string& path, const LoadOptions& options) {
    // The loader boundary: tinygltf (through nlohmann json) and std::bad_alloc may throw; nothing
    // escapes, and every error starts with the file path.
    try {
        Result<Scene> result = loadUnguarded(path, options);
        if (!result) return makeError(path + ": " + result.message());
        return result;
    } catch (const std::bad_alloc&) {
        return makeError(path + ": out of memory while loading (the file declares sizes too large to load)");
    } catch (const std::exception& e) {
        return makeError(path + ": invalid glTF (" + std::string(e.what()) + ")");
    } catch (...) {
        return makeError(path + ": invalid glTF (unknown exception while parsing)");
    }
}

}  // namespace caustics::scene
