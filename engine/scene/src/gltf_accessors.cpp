#include <cmath>
#include <cstring>

#include "gltf_internal.h"

namespace caustics::scene::gltf {

static int componentBytes(int componentType) {
    switch (componentType) {
        case TINYGLTF_COMPONENT_TYPE_BYTE:
        case TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE: return 1;
        case TINYGLTF_COMPONENT_TYPE_SHORT:
        case TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT: return 2;
        case TINYGLTF_COMPONENT_TYPE_INT:
        case TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT:
        case TINYGLTF_COMPONENT_TYPE_FLOAT: return 4;
        default: return 0;
    }
}

static int componentCount(int type) {
    switch (type) {
        case TINYGLTF_TYPE_SCALAR: return 1;
        case TINYGLTF_TYPE_VEC2: return 2;
        case TINYGLTF_TYPE_VEC3: return 3;
        case TINYGLTF_TYPE_VEC4: return 4;
        case TINYGLTF_TYPE_MAT2: return 4;
        case TINYGLTF_TYPE_MAT3: return 9;
        case TINYGLTF_TYPE_MAT4: return 16;
        default: return 0;
    }
}

const char* typeName(int type) {
    switch (type) {
        case TINYGLTF_TYPE_SCALAR: return "SCALAR";
        case TINYGLTF_TYPE_VEC2: return "VEC2";
        case TINYGLTF_TYPE_VEC3: return "VEC3";
        case TINYGLTF_TYPE_VEC4: return "VEC4";
        case TINYGLTF_TYPE_MAT2: return "MAT2";
        case TINYGLTF_TYPE_MAT3: return "MAT3";
        case TINYGLTF_TYPE_MAT4: return "MAT4";
        default: return "unknown type";
    }
}

const char* componentTypeName(int componentType) {
    switch (componentType) {
        case TINYGLTF_COMPONENT_TYPE_BYTE: return "BYTE";
        case TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE: return "UNSIGNED_BYTE";
        case TINYGLTF_COMPONENT_TYPE_SHORT: return "SHORT";
        case TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT: return "UNSIGNED_SHORT";
        case TINYGLTF_COMPONENT_TYPE_INT: return "INT";
        case TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT: return "UNSIGNED_INT";
        case TINYGLTF_COMPONENT_TYPE_FLOAT: return "FLOAT";
        case TINYGLTF_COMPONENT_TYPE_DOUBLE: return "DOUBLE";
        default: return "unknown componentType";
    }
}

Result<AccessorView> viewAccessor(const tinygltf::Model& model, int index, const std::string& what,
                                  uint64_t maxCount) {
    std::string name = "accessor " + std::to_string(index) + " (" + what + ")";
    if (index < 0 || size_t(index) >= model.accessors.size())
        return makeError(name + " does not exist: the file has " + std::to_string(model.accessors.size()) +
                         " accessors");
    const tinygltf::Accessor& acc = model.accessors[size_t(index)];
    if (acc.sparse.isSparse) return makeError(name + " is sparse; sparse accessors are not supported");
    if (acc.count > maxCount)
        return makeError(name + " has count " + std::to_string(acc.count) + ", more than the limit " +
                         std::to_string(maxCount));
    int compBytes = componentBytes(acc.componentType);
    int comps = componentCount(acc.type);
    if (compBytes == 0 || comps == 0)
        return makeError(name + " has an invalid type/componentType (" + std::to_string(acc.type) + "/" +
                         std::to_string(acc.componentType) + ")");
    if (acc.bufferView < 0 || size_t(acc.bufferView) >= model.bufferViews.size())
        return makeError(name + " refers to buffer view " + std::to_string(acc.bufferView) + ", but the file has " +
                         std::to_string(model.bufferViews.size()) + " buffer views");
    const tinygltf::BufferView& bv = model.bufferViews[size_t(acc.bufferView)];
    if (bv.buffer < 0 || size_t(bv.buffer) >= model.buffers.size())
        return makeError("buffer view " + std::to_string(acc.bufferView) + " refers to buffer " +
                         std::to_string(bv.buffer) + ", but the file has " + std::to_string(model.buffers.size()) +
                         " buffers");
    const tinygltf::Buffer& buf = model.buffers[size_t(bv.buffer)];
    // All sizes fit in 64 bits: count <= maxCount (< 2^40), stride <= 255 (or checked below).
    uint64_t bvEnd = uint64_t(bv.byteOffset) + uint64_t(bv.byteLength);
    if (bv.byteOffset > buf.data.size() || bv.byteLength > buf.data.size() || bvEnd > buf.data.size())
        return makeError("buffer view " + std::to_string(acc.bufferView) + " (bytes " + std::to_string(bv.byteOffset) +
                         ".." + std::to_string(bvEnd) + ") is out of range of buffer " + std::to_string(bv.buffer) +
                         " (" + std::to_string(buf.data.size()) + " bytes)");
    uint64_t elemBytes = uint64_t(compBytes) * uint64_t(comps);
    uint64_t stride = bv.byteStride ? uint64_t(bv.byteStride) : elemBytes;
    if (stride < elemBytes || stride > 252)
        return makeError(name + ": byteStride " + std::to_string(stride) + " of buffer view " +
                         std::to_string(acc.bufferView) + " is invalid for " + std::to_string(elemBytes) +
                         "-byte elements");
    if (acc.byteOffset > bv.byteLength)
        return makeError(name + " (byteOffset " + std::to_string(acc.byteOffset) +
                         ") is out of range of its buffer view " + std::to_string(acc.bufferView) + " (" +
                         std::to_string(bv.byteLength) + " bytes)");
    uint64_t needed = acc.count == 0 ? 0 : uint64_t(acc.byteOffset) + (uint64_t(acc.count) - 1) * stride + elemBytes;
    if (needed > bv.byteLength)
        return makeError(name + " (count " + std::to_string(acc.count) + ", byteOffset " +
                         std::to_string(acc.byteOffset) + ", stride " + std::to_string(stride) + ", needs " +
                         std::to_string(needed) + " bytes) is out of range of its buffer view " +
                         std::to_string(acc.bufferView) + " (" + std::to_string(bv.byteLength) + " bytes)");
    AccessorView view;
    view.data = buf.data.data() + bv.byteOffset + acc.byteOffset;
    view.stride = size_t(stride);
    view.count = size_t(acc.count);
    view.componentType = acc.componentType;
    view.components = comps;
    view.normalized = acc.normalized;
    return view;
}

template <typename T>
static T loadAt(const uint8_t* p) {
    T v;
    std::memcpy(&v, p, sizeof(T));
    return v;
}

float readFloat(const AccessorView& v, size_t i, int c) {
    const uint8_t* p = v.data + i * v.stride;
    switch (v.componentType) {
        case TINYGLTF_COMPONENT_TYPE_FLOAT: return loadAt<float>(p + 4 * c);
        // glTF 2.0 3.11: normalized integer to float.
        case TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE: {
            float f = float(p[c]);
            return v.normalized ? f / 255.0f : f;
        }
        case TINYGLTF_COMPONENT_TYPE_BYTE: {
            float f = float(int8_t(p[c]));
            return v.normalized ? std::max(f / 127.0f, -1.0f) : f;
        }
        case TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT: {
            float f = float(loadAt<uint16_t>(p + 2 * c));
            return v.normalized ? f / 65535.0f : f;
        }
        case TINYGLTF_COMPONENT_TYPE_SHORT: {
            float f = float(loadAt<int16_t>(p + 2 * c));
            return v.normalized ? std::max(f / 32767.0f, -1.0f) : f;
        }
        case TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT: return float(loadAt<uint32_t>(p + 4 * c));
        case TINYGLTF_COMPONENT_TYPE_INT: return float(loadAt<int32_t>(p + 4 * c));
        default: return 0.0f;
    }
}

uint32_t readIndex(const AccessorView& v, size_t i) {
    const uint8_t* p = v.data + i * v.stride;
    switch (v.componentType) {
        case TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE: return p[0];
        case TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT: return loadAt<uint16_t>(p);
        case TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT: return loadAt<uint32_t>(p);
        default: return 0;
    }
}

const tinygltf::Value* member(const tinygltf::Value& object, const char* key) {
    if (!object.IsObject() || !object.Has(key)) return nullptr;
    return &object.Get(key);
}

float numberOr(const tinygltf::Value& object, const char* key, float fallback) {
    const tinygltf::Value* v = member(object, key);
    if (!v || !v->IsNumber()) return fallback;
    double d = v->GetNumberAsDouble();
    return std::isfinite(d) ? float(d) : fallback;
}

int intOr(const tinygltf::Value& object, const char* key, int fallback) {
    const tinygltf::Value* v = member(object, key);
    if (!v || !v->IsNumber()) return fallback;
    double d = v->GetNumberAsDouble();
    return (std::isfinite(d) && d >= -2147483648.0 && d <= 2147483647.0) ? int(d) : fallback;
}

glm::vec3 vec3Or(const tinygltf::Value& object, const char* key, const glm::vec3& fallback) {
    const tinygltf::Value* v = member(object, key);
    if (!v || !v->IsArray() || v->ArrayLen() < 3) return fallback;
    glm::vec3 out;
    for (int i = 0; i < 3; ++i) {
        const tinygltf::Value& e = v->Get(i);
        if (!e.IsNumber() || !std::isfinite(e.GetNumberAsDouble())) return fallback;
        out[i] = float(e.GetNumberAsDouble());
    }
    return out;
}

}  // namespace caustics::scene::gltf
