// Bindings declared once (docs/shaders.md, "Bindings"): the generator writes the declaration's GLSL and
// HLSL spelling, and a pass fills its binding set by name with the declared slots (passes/module/
// pass_bindings.h). The truth tests (binding_truth_test.cpp) then hold the generated text against the
// C++ layouts like any other shader.
#include <gtest/gtest.h>

#include "binding_checker.h"
#include "composite/composite_bindings.h"
#include "module/pass_bindings.h"

namespace caustics::test {
namespace {

const shader_bindings::PassBindings& kComposite = shader_bindings::kCompositeBindings;

std::string generated(const char* language, const char* pass) {
    return readTextFile(std::string(CAUSTICS_GENERATED_SHADERS_DIR) + "/" + language + "/bindings/" + pass + ".h")
        .value_or("");
}

TEST(PassBindings, GeneratedGlslSpellsEachDeclaredBinding) {
    const std::string glsl = generated("glsl", "composite");
    ASSERT_FALSE(glsl.empty());
    EXPECT_NE(glsl.find("layout(set = 0, binding = 0) uniform texture2D direct;"), std::string::npos) << glsl;
    EXPECT_NE(glsl.find("layout(set = 0, binding = 5, rgba8) uniform image2D display;"), std::string::npos) << glsl;
    EXPECT_NE(glsl.find("layout(push_constant) uniform CompositeParamsPush { CompositeParams params; };"),
              std::string::npos) << glsl;
}

TEST(PassBindings, GeneratedHlslSpellsEachDeclaredBindingInItsRegisterClass) {
    const std::string hlsl = generated("hlsl", "composite");
    ASSERT_FALSE(hlsl.empty());
    EXPECT_NE(hlsl.find("Texture2D<float4> direct : register(t0, space0);"), std::string::npos) << hlsl;
    EXPECT_NE(hlsl.find("RWTexture2D<unorm float4> display : register(u5, space0);"), std::string::npos) << hlsl;
    EXPECT_NE(hlsl.find("RWTexture2D<float4> hdr : register(u6, space0);"), std::string::npos) << hlsl;
    EXPECT_NE(hlsl.find("ConstantBuffer<CompositeParams> params : register(b0, space999);"), std::string::npos) << hlsl;
}

TEST(PassBindings, SetIsFilledByNameWithTheDeclaredSlotsAndKinds) {
    PassBindingSet set(kComposite, 0);
    for (const char* name : {"direct", "caustics", "albedoMetallic", "normalRoughness", "linearDepth", "display", "hdr"})
        set.texture(name, nullptr);
    auto desc = set.desc();
    ASSERT_TRUE(desc.ok()) << desc.message();
    ASSERT_EQ(desc->items.size(), 7u);
    EXPECT_EQ(desc->items[1].slot, 1u);
    EXPECT_EQ(desc->items[1].type, rhi::BindingType::SampledTexture);
    EXPECT_EQ(desc->items[6].slot, 6u);
    EXPECT_EQ(desc->items[6].type, rhi::BindingType::StorageTexture);
}

TEST(PassBindings, UnknownWrongKindAndMissingBindingsAreErrorsNamingThem) {
    auto desc = PassBindingSet(kComposite, 0)
                    .texture("direct", nullptr)
                    .texture("directLight", nullptr)
                    .buffer("caustics", nullptr)
                    .desc();
    ASSERT_FALSE(desc.ok());
    const std::string& m = desc.message();
    EXPECT_NE(m.find("composite bindings (set 0)"), std::string::npos) << m;
    EXPECT_NE(m.find("'directLight' (texture) is not a binding of set 0"), std::string::npos) << m;
    EXPECT_NE(m.find("'caustics' is declared as a sampled texture, not a buffer"), std::string::npos) << m;
    EXPECT_NE(m.find("'hdr' is not set"), std::string::npos) << m;
}

}  // namespace
}  // namespace caustics::test
