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
// The same limit on where geometry lies: a vertex 1e9 m out leaves a float ray no precision anywhere
// near it, and the camera's far plane (fitted to the bounds) no depth precision (a black image).
constexpr double kMaxCoordinate = 1e6;

// Largest |p| over the mesh's vertices, in double.
double meshRadius(const Mesh& mesh) {
    double r = 0.0;
    for (const glm::vec3& p : mesh.positions) r = std::max(r, std::sqrt(double(p.x) * p.x + double(p.y) * p.y + double(p.z) * p.z));
    return r;
}

// Triangles whose area is zero (in double: float cross products of large coordinates round to zero).
size_t zeroAreaTriangles(const Mesh& mesh) {
    size_t zero = 0;
    for (size_t t = 0; t + 2 < mesh.indices.size(); t += 3) {
        glm::dvec3 a(mesh.positions[mesh.indices[t]]), b(mesh.positions[mesh.indices[t + 1]]), c(mesh.positions[mesh.indices[t + 2]]);
        if (!(glm::length(glm::cross(b - a, c - a)) > 0.0)) ++zero;
    }
    return zero;
}

std::string numbers(const double* v, size_t n) {
    std::string out = "(";
    for (size_t i = 0; i < n; ++i) {
        char text[32];
        std::snprintf(text, sizeof(text), "%s%.6g", i ? ", " : "", v[i]);
        out += text;
    }
    return out + ")";
}

// glTF 2.0 5.25: `matrix` must be decomposable to TRS, so its bottom row is (0, 0, 0, 1); `rotation` is a
// unit quaternion. A projective matrix is refused (the renderer's instances are affine 3x4: it would
// silently drop the row); a quaternion that is not unit is normalised, a zero one ignored, with a warning.
Result<glm::mat4> localTransform(const tinygltf::Node& node, size_t index, std::vector<std::string>& warnings) {
    glm::mat4 m(1.0f);
    std::string name = nodeLabel(node, index);
    if (!node.matrix.empty()) {
        if (node.matrix.size() != 16) return makeError(name + " has a matrix of " + std::to_string(node.matrix.size()) + " numbers, expected 16");
        for (int i = 0; i < 16; ++i) glm::value_ptr(m)[i] = float(node.matrix[size_t(i)]);   // column-major, as glTF
        const double bottom[4] = {node.matrix[3], node.matrix[7], node.matrix[11], node.matrix[15]};
        if (std::fabs(bottom[0]) > 1e-6 || std::fabs(bottom[1]) > 1e-6 || std::fabs(bottom[2]) > 1e-6 ||
            std::fabs(bottom[3] - 1.0) > 1e-6)
            return makeError(name + " has a matrix whose bottom row is " + numbers(bottom, 4) +
                             ", not (0, 0, 0, 1): glTF 2.0 node matrices must be affine (decomposable to TRS)");
    } else {
        glm::vec3 t(0.0f), s(1.0f);
        glm::quat r(1.0f, 0.0f, 0.0f, 0.0f);
        if (node.translation.size() == 3) t = {float(node.translation[0]), float(node.translation[1]), float(node.translation[2])};
        if (node.scale.size() == 3) s = {float(node.scale[0]), float(node.scale[1]), float(node.scale[2])};
        if (node.rotation.size() == 4) {   // glTF stores (x, y, z, w)
            const double* q = node.rotation.data();
            double length = std::sqrt(q[0] * q[0] + q[1] * q[1] + q[2] * q[2] + q[3] * q[3]);
            if (!(length > 1e-12) || !std::isfinite(length)) {
                warnings.push_back(name + " has rotation " + numbers(q, 4) +
                                   ", not a unit quaternion (glTF 2.0 5.25); using no rotation");
            } else {
                if (std::fabs(length - 1.0) > 1e-3) {
                    char text[32];
                    std::snprintf(text, sizeof(text), "%.6g", length);
                    warnings.push_back(name + " has rotation " + numbers(q, 4) + " of length " + text +
                                       ", not a unit quaternion (glTF 2.0 5.25); normalised");
                }
                r = glm::quat(float(q[3] / length), float(q[0] / length), float(q[1] / length), float(q[2] / length));
            }
        }
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
    std::string firstSkip_;   // why the first instance was skipped
    uint32_t degeneratePrimitives_ = 0;
    std::vector<double> meshRadius_;   // scene mesh -> largest |local vertex|
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
    for (size_t i = 0; i < model_.materials.size(); ++i)
        scene.materials.push_back(convertMaterial(model_.materials[i], i, textureToImage, options_.maxLightIntensity, warnings));

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
            size_t triangles = mesh.indices.size() / 3;
            if (triangles > 0 && zeroAreaTriangles(mesh) == triangles) {
                warnings.push_back("mesh " + std::to_string(m) + " primitive " + std::to_string(p) + ": all " +
                                   std::to_string(triangles) + " triangles have zero area (nothing to render); skipped");
                ++degeneratePrimitives_;
                continue;
            }
            if (prim.material >= 0 && size_t(prim.material) >= model_.materials.size())
                return makeError("mesh " + std::to_string(m) + " primitive " + std::to_string(p) + " refers to material " +
                                 std::to_string(prim.material) + ", but the file has " +
                                 std::to_string(model_.materials.size()) + " materials");
            mesh.material = prim.material >= 0 ? uint32_t(prim.material) : defaultMaterial(scene);
            meshPrimitives_[m].push_back(uint32_t(scene.meshes.size()));
            meshRadius_.push_back(meshRadius(mesh));
            scene.meshes.push_back(std::move(mesh));
        }
    }
    if (scene.meshes.empty() && degeneratePrimitives_ > 0)
        return makeError("has no triangle of non-zero area (" + std::to_string(degeneratePrimitives_) +
                         " primitives, every triangle degenerate): the image would be empty");
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
        CAUSTICS_TRY(glm::mat4 local, localTransform(node, size_t(index), warnings));
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
            if (skippedInstances_++ == 0) firstSkip_ = warnings.back();
        }
        if (node.mesh >= 0 && !hugeScale) {
            if (size_t(node.mesh) >= model_.meshes.size())
                return makeError("node " + std::to_string(index) + " refers to mesh " + std::to_string(node.mesh) + ", but the file has " +
                                 std::to_string(model_.meshes.size()) + " meshes");
            double radius = 0.0;
            for (uint32_t sm : meshPrimitives_[size_t(node.mesh)]) radius = std::max(radius, meshRadius_[sm]);
            glm::dvec3 origin(world[3]);
            double reach = glm::length(origin) + maxAxisScale(world) * radius;
            const bool farOut = reach > kMaxCoordinate;
            if (farOut) {
                char text[32];
                std::snprintf(text, sizeof(text), "%.3g", reach);
                warnings.push_back(nodeLabel(node, size_t(index)) + " places its mesh up to " + text + " m from the origin " +
                                   "(more than 1e6 m): float ray tracing cannot represent it; the instance is skipped");
                if (skippedInstances_++ == 0) firstSkip_ = warnings.back();
            }
            for (uint32_t sm : meshPrimitives_[size_t(node.mesh)]) {
                if (farOut) break;
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
            // Refused, not skipped: a skipped light leaves a file "without lights" that has one.
            double intensity = model_.lights[size_t(light)].intensity;
            if (!(intensity >= 0.0) || !std::isfinite(intensity)) {
                char text[32];
                std::snprintf(text, sizeof(text), "%.6g", intensity);
                return makeError(label + " has intensity " + text + "; KHR_lights_punctual requires a finite intensity >= 0");
            }
            if (convertLight(model_.lights[size_t(light)], world, options_.maxLightIntensity, out, problem, repaired))
                scene.lights.push_back(out);
            else warnings.push_back(label + " " + problem + "; skipped");
            if (!repaired.empty()) warnings.push_back(label + ": " + repaired);
        }
        for (auto it = node.children.rbegin(); it != node.children.rend(); ++it) stack.push_back({*it, world});
    }
    if (scene.instances.empty() && skippedInstances_ > 0)
        return makeError("every mesh instance was skipped (" + std::to_string(skippedInstances_) + "), the image would be empty: " +
                         firstSkip_);
    if (scene.instances.empty()) {
        // Meshes no scene uses: show each once at the origin rather than render nothing.
        warnings.push_back("no node instantiates a mesh; every mesh is placed once at the origin");
        for (uint32_t m = 0; m < scene.meshes.size(); ++m) scene.instances.push_back({m, glm::mat4(1.0f), m + 1});
    }
    return okStatus();
}

Result<std::vector<unsigned char>> readFile(const std::string& path) {
    std::error_code ec;
    std::filesystem::file_status status = std::filesystem::status(path, ec);   // stat: a FIFO is not opened
    if (!std::filesystem::exists(status)) return makeError("file not found");
    if (std::filesystem::is_directory(status)) return makeError("is a directory, not a glTF file");
    if (!std::filesystem::is_regular_file(status))
        return makeError("is not a regular file (a device, FIFO or socket); only regular files are read");
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

// `name`: the file path or the memory load's name; `modelDir`: the file's folder ("" from memory).
Result<Scene> loadBytes(const std::vector<unsigned char>& bytes, const std::string& name, const std::string& modelDir,
                        const LoadOptions& options) {
    if (bytes.empty()) return makeError("the file is empty");
    std::filesystem::path fsPath(name);
    std::string ext = fsPath.extension().string();
    std::transform(ext.begin(), ext.end(), ext.begin(), [](unsigned char c) { return char(std::tolower(c)); });
    // The "glTF" magic decides, whatever the extension says (a GLB named .gltf is common).
    bool binary = bytes.size() >= 4 && std::memcmp(bytes.data(), "glTF", 4) == 0;
    if (ext == ".glb" && !binary) return makeError("is not a binary glTF file (no 'glTF' magic at the start)");
    if (bytes.size() > 0xFFFFFFFFull) return makeError("is larger than 4 GiB");
    CAUSTICS_TRY(AssetRoot assets, makeAssetRoot(modelDir, options.assetRoot));
    size_t jsonBegin = binary ? 20 : 0, jsonLength = bytes.size();
    if (binary) {
        CAUSTICS_CHECK(preflightGlb(bytes));   // the chunk lengths below are then within the file
        uint32_t chunk = 0;
        std::memcpy(&chunk, bytes.data() + 12, 4);
        jsonLength = chunk;
    }
    std::vector<std::string> preflightWarnings;
    if (jsonTooDeep(bytes.data() + jsonBegin, jsonLength))
        return makeError("invalid JSON: nesting deeper than " + std::to_string(kMaxJsonDepth) + " levels");
    CAUSTICS_CHECK(preflightJson(bytes.data() + jsonBegin, jsonLength, assets, preflightWarnings));
    for (const std::string& w : preflightWarnings) log(LogLevel::Warning, name + ": " + w);

    tinygltf::TinyGLTF loader;
    ImageContext imageContext{&options, {}};
    loader.SetImageLoader(decodeImage, &imageContext);
    loader.SetFsCallbacks(confinedFileSystem(assets));
    tinygltf::Model model;
    std::string err, warn;
    std::string baseDir = assets.modelDir.string();
    bool ok = binary ? loader.LoadBinaryFromMemory(&model, &err, &warn, bytes.data(), unsigned(bytes.size()), baseDir)
                     : loader.LoadASCIIFromString(&model, &err, &warn, reinterpret_cast<const char*>(bytes.data()),
                                                  unsigned(bytes.size()), baseDir);
    logLines(name, shortenLongWords(warn));
    if (!imageContext.error.empty()) return makeError(imageContext.error);
    if (!ok) return makeError(err.empty() ? std::string("tinygltf could not parse the file") : shortenLongWords(trimmed(err)));

    Scene scene;
    scene.name = fsPath.stem().string();
    Importer importer(model, options);
    Status status = importer.run(scene);
    for (const std::string& w : importer.warnings) log(LogLevel::Warning, name + ": " + w);
    if (!status) return status.error();
    return scene;
}

Result<Scene> loadUnguarded(const std::string& path, const LoadOptions& options) {
    CAUSTICS_TRY(std::vector<unsigned char> bytes, readFile(path));
    std::string folder = std::filesystem::path(path).parent_path().string();
    return loadBytes(bytes, path, folder.empty() ? "." : folder, options);
}

// The loader boundary: tinygltf (through nlohmann json) and std::bad_alloc may throw; nothing
// escapes, and every error starts with `name`.
template <typename Load>
Result<Scene> guarded(const std::string& name, Load&& load) {
    try {
        Result<Scene> result = load();
        if (!result) return makeError(name + ": " + result.message());
        return result;
    } catch (const std::bad_alloc&) {
        return makeError(name + ": out of memory while loading (the file declares sizes too large to load)");
    } catch (const std::exception& e) {
        return makeError(name + ": invalid glTF (" + std::string(e.what()) + ")");
    } catch (...) {
        return makeError(name + ": invalid glTF (unknown exception while parsing)");
    }
}

}  // namespace

Result<Scene> loadGltf(const std::string& path, const LoadOptions& options) {
    return guarded(path, [&] { return loadUnguarded(path, options); });
}

Result<Scene> loadGltfFromMemory(const std::vector<unsigned char>& bytes, const std::string& name, const LoadOptions& options) {
    return guarded(name, [&] { return loadBytes(bytes, name, "", options); });
}

}  // namespace caustics::scene
