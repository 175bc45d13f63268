// The scene's set declared once (passes/module/scene_set_bindings.h; docs/shaders.md, "Bindings"): what
// the generator writes for it, held against the shared-dialect structs compiled as C++ here. The
// BindingTruth tests then hold every shader that includes it against the C++ layout, like any other.
#include <cstddef>
#include <cstring>
#include <map>
#include <regex>
#include <set>

#include <gtest/gtest.h>

#include "binding_checker.h"
#include "common/scene.h"
#include "module/pass_bindings.h"
#include "module/scene_set_bindings.h"
#include "shader_preprocessor.h"
#include "struct_layout.h"

namespace caustics::test {
namespace {

namespace sb = shader_bindings;

std::string generated(const char* language) {
    return readTextFile(std::string(CAUSTICS_GENERATED_SHADERS_DIR) + "/" + language + "/bindings/scene.h").value_or("");
}

const sb::Binding& binding(std::string_view name) {
    for (const sb::Binding& b : sb::kSceneSetBindingList)
        if (b.name == name) return b;
    ADD_FAILURE() << "no scene binding " << name;
    return sb::kSceneSetBindingList[0];
}

bool contains(const std::string& text, const std::string& part) { return text.find(part) != std::string::npos; }

// The structs of common/scene.h as a GLSL shader reads them (comments stripped, includes resolved).
StructTable sceneStructs() {
    const std::string shaders = std::string(CAUSTICS_SOURCE_DIR) + "/shaders";
    PreprocessedShader p = preprocessShader(readTextFile(shaders + "/common/scene.h").value_or(""), {}, {shaders}, readTextFile);
    EXPECT_TRUE(p.problems.empty());
    return readStructs(p.text);
}

TEST(SceneSetBindings, StridesAndTheLightHeaderAreTheSharedStructsSizes) {
    // The generator cannot compile the structs (it is a dependency-free host tool), so the declaration
    // states their sizes; these are the C++ compilation of the same shared-dialect structs.
    EXPECT_EQ(binding("sceneVertices").stride, sizeof(shader::GpuVertex));
    EXPECT_EQ(binding("sceneMaterials").stride, sizeof(shader::GpuMaterial));
    EXPECT_EQ(binding("sceneInstances").stride, sizeof(shader::GpuInstance));
    EXPECT_EQ(binding("sceneLights").stride, sizeof(shader::GpuLight));
    EXPECT_EQ(binding("sceneLights").header, "GpuLightTableHeader");
    EXPECT_EQ(binding("sceneLights").headerBytes, sizeof(shader::GpuLightTableHeader));
}

TEST(SceneSetBindings, Std430PutsTheFirstLightWhereHlslReadsIt) {
    // GLSL places the array after the header member by std430 alignment; HLSL reads element i at
    // headerBytes + i * stride. Both must be the byte packLightBuffer writes the first light at.
    const StructTable structs = sceneStructs();
    StructLayoutResult both = structSize("{ GpuLightTableHeader header; GpuLight first; }", structs, LayoutRules::Std430);
    StructLayoutResult light = structSize("GpuLight", structs, LayoutRules::Std430);
    ASSERT_TRUE(both.problem.empty() && light.problem.empty()) << both.problem << light.problem;
    EXPECT_EQ(both.bytes - light.bytes, binding("sceneLights").headerBytes);

    const std::string glsl = generated("glsl"), hlsl = generated("hlsl");
    EXPECT_TRUE(contains(glsl, "{ GpuLightTableHeader sceneLightsHeader; GpuLight sceneLights[]; };")) << glsl;
    EXPECT_TRUE(contains(hlsl, "return sceneLights.Load<GpuLightTableHeader>(0u);")) << hlsl;
    EXPECT_TRUE(contains(hlsl, "return sceneLights.Load<GpuLight>(16u + i * 64u);")) << hlsl;
}

TEST(SceneSetBindings, TextureArrayHasItsCountInBothLanguages) {
    const uint32_t count = sb::kSceneTextureCount;
    EXPECT_EQ(binding("sceneTextures").count, count);
    for (auto [language, text] : {std::pair{ShaderLanguage::Glsl, generated("glsl")},
                                  std::pair{ShaderLanguage::Hlsl, generated("hlsl")}}) {
        ShaderInterface iface = readShaderInterface(language, text);
        EXPECT_TRUE(iface.problems.empty());
        bool found = false;
        for (const DeclaredBinding& d : iface.bindings)
            if (d.name == "sceneTextures") {
                found = true;
                EXPECT_EQ(d.slot, binding("sceneTextures").slot);
                EXPECT_EQ(d.arraySize, count) << d.spelling;
            }
        EXPECT_TRUE(found) << text;
    }
}

TEST(SceneSetBindings, GuardsLeaveTheTlasAndTheTexturesOut) {
    // Raster and compute shaders define SCENE_NO_TLAS; passes reading no texture SCENE_NO_TEXTURES.
    for (auto [language, text] : {std::pair{ShaderLanguage::Glsl, generated("glsl")},
                                  std::pair{ShaderLanguage::Hlsl, generated("hlsl")}}) {
        auto slots = [&](const std::string& defines) {
            std::set<uint32_t> s;
            for (const DeclaredBinding& d : readShaderInterface(language, defines + text).bindings) s.insert(d.slot);
            return s;
        };
        EXPECT_EQ(slots(""), (std::set<uint32_t>{0, 1, 2, 3, 4, 5, 6, 7, 8}));
        EXPECT_EQ(slots("#define SCENE_NO_TLAS\n"), (std::set<uint32_t>{1, 2, 3, 4, 5, 6, 7, 8}));
        EXPECT_EQ(slots("#define SCENE_NO_TLAS\n#define SCENE_NO_TEXTURES\n"), (std::set<uint32_t>{1, 2, 3, 4, 5, 6}));
    }
}

// The 16 floats of a C++ matrix member as the generated HLSL reads them: loadFloat4x4 (common/lang.h)
// builds a float4x4 from the rows Load4(offset + 16 r) and transposes it, so HLSL element [row][col] is
// the float at offset + 16 col + 4 row, which is glm's m[col][row] when offset is the member's.
glm::mat4 hlslLoadFloat4x4(const uint8_t* bytes, uint32_t offset) {
    glm::mat4 m;
    for (int col = 0; col < 4; ++col)
        for (int row = 0; row < 4; ++row) std::memcpy(&m[col][row], bytes + offset + 16 * col + 4 * row, 4);
    return m;
}

TEST(SceneSetBindings, HlslReadsEachInstanceMatrixInTheCppElementOrder) {
    // The emulation above is what lang.h spells.
    const std::string lang = readTextFile(std::string(CAUSTICS_SOURCE_DIR) + "/shaders/common/lang.h").value_or("");
    EXPECT_TRUE(contains(lang, "return transpose(float4x4(asfloat(b.Load4(offset)), asfloat(b.Load4(offset + 16u)), "
                               "asfloat(b.Load4(offset + 32u)),\n                              asfloat(b.Load4(offset + 48u))));"))
        << "common/lang.h loadFloat4x4 changed: update hlslLoadFloat4x4 here";

    shader::GpuInstance instance{};
    for (int col = 0; col < 4; ++col)
        for (int row = 0; row < 4; ++row) {
            instance.objectToWorld[col][row] = float(10 * col + row);
            instance.normalToWorld[col][row] = float(100 + 10 * col + row);
        }
    uint8_t bytes[sizeof(instance)];
    std::memcpy(bytes, &instance, sizeof(instance));
    const std::map<std::string, const glm::mat4*> members = {{"objectToWorld", &instance.objectToWorld},
                                                             {"normalToWorld", &instance.normalToWorld}};

    // Every float4x4 member of the shared struct is read column by column, at the offset the generated
    // HLSL names.
    const std::string hlsl = generated("hlsl");
    const std::regex read("v\\.(\\w+) = loadFloat4x4\\(sceneInstances, at \\+ (\\d+)u\\);");
    std::set<std::string> seen;
    for (std::sregex_iterator it(hlsl.begin(), hlsl.end(), read), end; it != end; ++it) {
        const std::string name = (*it)[1];
        ASSERT_TRUE(members.count(name)) << name;
        seen.insert(name);
        EXPECT_EQ(hlslLoadFloat4x4(bytes, uint32_t(std::stoul((*it)[2]))), *members.at(name)) << name;
    }
    EXPECT_EQ(seen.size(), members.size()) << hlsl;
    size_t matrices = 0;
    const StructTable structs = sceneStructs();
    ASSERT_TRUE(structs.count("GpuInstance"));
    for (const StructMember& m : structs.at("GpuInstance"))   // float4x4, spelled mat4 in GLSL
        matrices += m.type == "mat4" || m.type == "float4x4" ? m.count : 0;
    EXPECT_EQ(matrices, members.size()) << "a float4x4 member of GpuInstance is not read column by column";
    EXPECT_EQ(binding("sceneInstances").matrices.size(), matrices);
}

TEST(SceneSetBindings, TextureArrayIsFilledWithExactlyItsCount) {
    std::vector<rhi::TextureHandle> tooFew(3);
    auto desc = PassBindingSet(sb::kSceneSetBindings, 0).textures("sceneTextures", tooFew).desc();
    ASSERT_FALSE(desc.ok());
    EXPECT_TRUE(contains(desc.message(), "'sceneTextures' is an array of 256, given 3 textures")) << desc.message();
    EXPECT_TRUE(contains(desc.message(), "'sceneTlas' is not set")) << desc.message();
}

}  // namespace
}  // namespace caustics::test
