// Build-time tool: writes the GLSL and HLSL declarations of every pass's shader resources, and of the
// scene's set they share, from their one C++ declaration (shader_binding.h; docs/shaders.md, "Bindings").
// Usage: generate_bindings OUT_DIR NAME...   writes OUT_DIR/glsl/bindings/<NAME>.h and
// OUT_DIR/hlsl/bindings/<NAME>.h (one include path per language, so a body includes
// "bindings/<NAME>.h" in both) for each declaration and fails if the names given (the outputs CMake expects) are not exactly the declared ones.
#include <filesystem>
#include <fstream>
#include <iostream>
#include <set>
#include <string>
#include <vector>

#include "pass_binding_list.h"

namespace fs = std::filesystem;
using namespace caustics::shader_bindings;

namespace {

std::string str(std::string_view s) { return std::string(s); }

// std430 = tight size of the built-in element types a binding may name; 0 for a struct.
uint32_t builtinStride(std::string_view t) {
    if (t == "uint" || t == "int" || t == "float") return 4;
    if (t == "uint2" || t == "int2" || t == "float2") return 8;
    if (t == "uint4" || t == "int4" || t == "float4") return 16;
    return 0;
}

// Byte offset of element i of a storage buffer: after its header, if it has one.
std::string elementAt(const Binding& b, uint32_t stride) {
    const std::string scaled = "i * " + std::to_string(stride) + "u";
    return b.headerBytes ? std::to_string(b.headerBytes) + "u + " + scaled : scaled;
}

// Raw-buffer access of element i: Load/Load2/Load4 with asfloat/asint for the built-in types (any
// shader model), the templated Load<T>/Store<T> (StructuredBuffer layout) for a struct.
std::string hlslRawLoad(const Binding& b, uint32_t stride) {
    const std::string name = str(b.name), element = str(b.element), at = "(" + elementAt(b, stride) + ")";
    if (!builtinStride(b.element)) return name + ".Load<" + element + ">" + at;
    const uint32_t n = builtinStride(b.element) / 4;
    const std::string load = name + ".Load" + (n > 1 ? std::to_string(n) : "") + at;
    if (element.rfind("float", 0) == 0) return "asfloat(" + load + ")";
    if (element.rfind("int", 0) == 0) return "asint(" + load + ")";
    return load;
}

std::string hlslRawStore(const Binding& b, uint32_t stride) {
    const std::string name = str(b.name), at = elementAt(b, stride);
    if (!builtinStride(b.element)) return name + ".Store<" + str(b.element) + ">(" + at + ", v)";
    const uint32_t n = builtinStride(b.element) / 4;
    return name + ".Store" + (n > 1 ? std::to_string(n) : "") + "(" + at + ", asuint(v))";
}

// <name>Load(i) of a struct with float4x4 members: the struct, then each matrix again column by column
// (MatrixMember in shader_binding.h says why).
std::string hlslLoadWithMatrices(const Binding& b, uint32_t stride) {
    const std::string name = str(b.name), element = str(b.element);
    std::string s = element + " " + name + "Load(uint i) {\n    uint at = " + elementAt(b, stride) + ";\n    " + element +
                    " v = " + name + ".Load<" + element + ">(at);\n";
    for (const MatrixMember& m : b.matrices)
        s += "    v." + str(m.name) + " = loadFloat4x4(" + name + ", at + " + std::to_string(m.offset) + "u);\n";
    return s + "    return v;\n}\n";
}

std::string glslType(std::string_view t) {
    static const std::pair<const char*, const char*> kMap[] = {
        {"float2", "vec2"}, {"float3", "vec3"}, {"float4", "vec4"}, {"uint2", "uvec2"}, {"uint3", "uvec3"},
        {"uint4", "uvec4"}, {"int2", "ivec2"}, {"int3", "ivec3"}, {"int4", "ivec4"}};
    for (auto [from, to] : kMap)
        if (t == from) return to;
    return str(t);
}

const char* glslFormat(ImageFormat f) {
    switch (f) {
        case ImageFormat::Rgba8: return "rgba8";
        case ImageFormat::Rgba16f: return "rgba16f";
        case ImageFormat::Rgba32f: return "rgba32f";
        case ImageFormat::R32f: return "r32f";
        case ImageFormat::R32ui: return "r32ui";
        case ImageFormat::Rg32ui: return "rg32ui";
        case ImageFormat::Rgba32ui: return "rgba32ui";
        case ImageFormat::None: break;
    }
    return "";
}

const char* hlslImageElement(ImageFormat f) {
    switch (f) {
        case ImageFormat::Rgba8: return "unorm float4";
        case ImageFormat::R32f: return "float";
        case ImageFormat::R32ui: return "uint";
        case ImageFormat::Rg32ui: return "uint2";
        case ImageFormat::Rgba32ui: return "uint4";
        default: return "float4";
    }
}

bool isUint(std::string_view element) { return element.rfind("uint", 0) == 0; }
bool isInt(std::string_view element) { return element.rfind("int", 0) == 0; }

std::string layoutHead(const Binding& b, const char* extra = nullptr) {
    std::string s = "layout(set = " + std::to_string(b.set) + ", binding = " + std::to_string(b.slot);
    if (extra && *extra) s += std::string(", ") + extra;
    return s + ")";
}

std::string registerOf(const Binding& b, char cls) {
    return " : register(" + std::string(1, cls) + std::to_string(b.slot) + ", space" + std::to_string(b.set) + ");\n";
}

bool writeDeclaration(const Binding& b, std::string& glsl, std::string& hlsl, std::string& error) {
    const std::string name = str(b.name), element = str(b.element);
    const uint32_t stride = b.stride ? b.stride : builtinStride(b.element);
    switch (b.kind) {
        case Kind::ConstantBuffer:
            glsl += layoutHead(b, "std140") + " uniform " + name + "Block { " + element + " " + name + "; };\n";
            hlsl += "ConstantBuffer<" + element + "> " + name + registerOf(b, 'b');
            return true;
        case Kind::StorageBufferRO:
        case Kind::StorageBufferRW: {
            if (!stride) {
                error = name + ": a storage buffer of struct " + element + " needs its std430 stride";
                return false;
            }
            const bool rw = b.kind == Kind::StorageBufferRW;
            if (rw && !b.matrices.empty()) {
                error = name + ": a writable storage buffer of a struct with matrices is not generated";
                return false;
            }
            if (b.header.empty() != (b.headerBytes == 0)) {
                error = name + ": a header needs both its struct and its size";
                return false;
            }
            const std::string header = b.header.empty() ? "" : str(b.header) + " " + name + "Header; ";
            glsl += layoutHead(b, "std430") + (rw ? " buffer " : " readonly buffer ") + name + "Buffer { " + header +
                    glslType(b.element) + " " + name + "[]; };\n";
            glsl += glslType(b.element) + " " + name + "Load(uint i) { return " + name + "[i]; }\n";
            if (rw) glsl += "void " + name + "Store(uint i, " + glslType(b.element) + " v) { " + name + "[i] = v; }\n";
            hlsl += std::string(rw ? "RWByteAddressBuffer " : "ByteAddressBuffer ") + name + registerOf(b, rw ? 'u' : 't');
            if (!b.header.empty()) {
                glsl += str(b.header) + " " + name + "LoadHeader() { return " + name + "Header; }\n";
                hlsl += str(b.header) + " " + name + "LoadHeader() { return " + name + ".Load<" + str(b.header) + ">(0u); }\n";
            }
            if (b.matrices.empty()) hlsl += element + " " + name + "Load(uint i) { return " + hlslRawLoad(b, stride) + "; }\n";
            else hlsl += hlslLoadWithMatrices(b, stride);
            if (rw) hlsl += "void " + name + "Store(uint i, " + element + " v) { " + hlslRawStore(b, stride) + "; }\n";
            if (rw && element == "uint") {
                // A counter: <name>AtomicAdd(i, v) adds v to element i and returns the value before.
                glsl += "uint " + name + "AtomicAdd(uint i, uint v) { return atomicAdd(" + name + "[i], v); }\n";
                hlsl += "uint " + name + "AtomicAdd(uint i, uint v) { uint old; " + name +
                        ".InterlockedAdd(" + elementAt(b, 4) + ", v, old); return old; }\n";
            }
            return true;
        }
        case Kind::SampledTexture: {
            const char* prefix = isUint(b.element) ? "u" : (isInt(b.element) ? "i" : "");
            const std::string dim = b.textureArray ? "2DArray" : "2D";
            // A descriptor array (count > 1) is indexed by the shader: name[i].
            const std::string array = b.count > 1 ? "[" + std::to_string(b.count) + "]" : "";
            glsl += layoutHead(b) + " uniform " + prefix + "texture" + dim + " " + name + array + ";\n";
            hlsl += "Texture" + dim + "<" + element + "> " + name + array + registerOf(b, 't');
            return true;
        }
        case Kind::StorageTexture: {
            if (b.format == ImageFormat::None) {
                error = name + ": a storage texture needs its format";
                return false;
            }
            const bool unsignedFormat =
                b.format == ImageFormat::R32ui || b.format == ImageFormat::Rg32ui || b.format == ImageFormat::Rgba32ui;
            const char* prefix = unsignedFormat ? "u" : "";
            glsl += layoutHead(b, glslFormat(b.format)) + " uniform " + prefix + "image2D " + name + ";\n";
            hlsl += std::string("RWTexture2D<") + hlslImageElement(b.format) + "> " + name + registerOf(b, 'u');
            return true;
        }
        case Kind::Sampler:
            glsl += layoutHead(b) + " uniform sampler " + name + ";\n";
            hlsl += "SamplerState " + name + registerOf(b, 's');
            return true;
        case Kind::AccelStruct:
            glsl += layoutHead(b) + " uniform accelerationStructureEXT " + name + ";\n";
            hlsl += "RaytracingAccelerationStructure " + name + registerOf(b, 't');
            return true;
    }
    error = name + ": unknown kind";
    return false;
}

// One binding, inside #ifndef <omitIf> when a shader may leave it out (the scene's TLAS in raster and
// compute shaders, which have no ray-tracing types; its textures where a pass reads none).
bool writeBinding(const Binding& b, std::string& glsl, std::string& hlsl, std::string& error) {
    if (b.count != 1 && (b.kind != Kind::SampledTexture || b.count == 0)) {
        error = str(b.name) + ": only sampled textures are declared as arrays";
        return false;
    }
    if (b.omitIf.empty()) return writeDeclaration(b, glsl, hlsl, error);
    const std::string open = "#ifndef " + str(b.omitIf) + "\n";
    glsl += open;
    hlsl += open;
    if (!writeDeclaration(b, glsl, hlsl, error)) return false;
    glsl += "#endif\n";
    hlsl += "#endif\n";
    return true;
}

bool writePass(const PassBindings& pass, const fs::path& dir, std::string& error) {
    const std::string banner = "// Generated by shaders/bindings/generate_bindings.cpp from " + str(pass.declaredIn) +
                               ": do not edit. The shader includes the shared-dialect structs it names first.\n";
    const std::string guard = "CAUSTICS_BINDINGS_" + str(pass.name);
    std::string glsl = banner + "#ifndef " + guard + "\n#define " + guard + "\n";
    std::string hlsl = glsl;
    for (const Binding& b : pass.bindings)
        if (!writeBinding(b, glsl, hlsl, error)) {
            error = str(pass.name) + ": " + error;
            return false;
        }
    if (!pass.pushType.empty()) {
        // Push constants: a Vulkan push-constant block / a root constant buffer in the backend's space999
        // (docs/d3d12.md).
        glsl += "layout(push_constant) uniform " + str(pass.pushType) + "Push { " + str(pass.pushType) + " " +
                str(pass.pushName) + "; };\n";
        hlsl += "ConstantBuffer<" + str(pass.pushType) + "> " + str(pass.pushName) + " : register(b0, space999);\n";
    }
    glsl += "#endif\n";
    hlsl += "#endif\n";
    for (auto [text, language] : {std::pair{&glsl, "glsl"}, std::pair{&hlsl, "hlsl"}}) {
        const fs::path path = dir / language / "bindings" / (str(pass.name) + ".h");
        fs::create_directories(path.parent_path());
        std::ifstream old(path, std::ios::binary);
        std::string current((std::istreambuf_iterator<char>(old)), std::istreambuf_iterator<char>());
        if (current == *text) continue;   // unchanged: keep the timestamp, no shader rebuild
        std::ofstream out(path, std::ios::binary);
        out << *text;
        if (!out) {
            error = "cannot write " + path.string();
            return false;
        }
    }
    return true;
}

}  // namespace

int main(int argc, char** argv) {
    if (argc < 2) {
        std::cerr << "usage: generate_bindings OUT_DIR NAME...\n";
        return 2;
    }
    const fs::path dir = argv[1];
    std::set<std::string> expected(argv + 2, argv + argc), declared;
    for (const PassBindings* pass : caustics::shader_bindings::kAllPasses) {
        std::string error;
        if (!declared.insert(str(pass->name)).second) {
            std::cerr << "generate_bindings: two declarations named " << pass->name << "\n";
            return 1;
        }
        if (!writePass(*pass, dir, error)) {
            std::cerr << "generate_bindings: " << error << "\n";
            return 1;
        }
    }
    if (declared != expected) {
        std::cerr << "generate_bindings: the declarations (shaders/bindings/pass_binding_list.h) and the names "
                     "CMake expects (shaders/bindings/CMakeLists.txt) differ\n";
        return 1;
    }
    return 0;
}
