// One binding truth: every pass shader, GLSL and HLSL, declares exactly the bindings, push-constant
// size and payload size that the C++ pass creates its pipeline with (docs/d3d12.md). Both shader
// variants are covered: float atomics (Vulkan with shaderFloatAtomicAdd) and fixed point (D3D12).
#include <filesystem>
#include <iostream>
#include <set>

#include <gtest/gtest.h>

#include "binding_checker.h"

namespace caustics::test {
namespace {

std::vector<RecordedPipeline> allPipelines() {
    std::vector<RecordedPipeline> all;
    // Float atomics; fixed point in uint32 words; fixed point in uint64 words (docs/caustics.md "Fixed point").
    for (auto [floatAtomics, int64Atomics] : {std::pair{true, false}, std::pair{false, false}, std::pair{false, true}}) {
        auto recorded = recordPassPipelines({floatAtomics, int64Atomics});
        EXPECT_TRUE(recorded.ok()) << (recorded.ok() ? "" : recorded.message());
        if (recorded.ok()) all.insert(all.end(), recorded.value().begin(), recorded.value().end());
    }
    return all;
}

std::string joined(const std::vector<std::string>& lines) {
    std::string s;
    for (const auto& l : lines) s += "  " + l + "\n";
    return s;
}

void expectShadersMatchCpp(ShaderLanguage language) {
    std::vector<std::string> errors;
    size_t checked = 0;
    for (const RecordedPipeline& p : allPipelines()) {
        auto e = checkPipelineBindings(p, language, CAUSTICS_SOURCE_DIR, readTextFile, &checked);
        errors.insert(errors.end(), e.begin(), e.end());
    }
    EXPECT_TRUE(errors.empty()) << errors.size() << " disagreement(s) with the C++ layouts:\n" << joined(errors);
    // The passes declare well over a hundred bindings across both variants (230 GLSL, 232 HLSL when
    // this was written); a parser that stopped seeing declarations would pass the check above vacuously.
    EXPECT_GT(checked, 100u);
    std::cout << checked << " shader binding declarations checked\n";
}

TEST(BindingTruth, EveryPassGlslDeclarationMatchesTheCppLayout) { expectShadersMatchCpp(ShaderLanguage::Glsl); }

TEST(BindingTruth, EveryPassHlslRegisterMatchesTheCppLayout) { expectShadersMatchCpp(ShaderLanguage::Hlsl); }

// The check covers what exists: every GLSL entry point of every pass belongs to a recorded pipeline
// (a shader no pipeline uses would escape it).
TEST(BindingTruth, EveryPassShaderEntryPointIsCreatedByAPass) {
    std::set<std::string> used;
    for (const RecordedPipeline& p : allPipelines())
        for (const RecordedShader& s : p.shaders) used.insert(s.name);
    namespace fs = std::filesystem;
    const fs::path root = fs::path(CAUSTICS_SOURCE_DIR) / "shaders" / "vulkan";
    const fs::path passes = fs::path(CAUSTICS_SOURCE_DIR) / "passes";
    const std::set<std::string> stages = {".rgen", ".rmiss", ".rchit", ".rahit", ".rint", ".comp", ".vert", ".frag"};
    int entryPoints = 0;
    for (const auto& f : fs::recursive_directory_iterator(root)) {
        if (!stages.count(f.path().extension().string())) continue;
        ++entryPoints;
        const std::string name = fs::relative(f.path(), root).generic_string();
        EXPECT_TRUE(used.count(name)) << "shaders/vulkan/" << name << " is not used by any pass pipeline";
    }
    // A pass's own entries, passes/<pass>/shaders/<file>, are looked up as "<pass>/<file>" (docs/shaders.md).
    for (const auto& pass : fs::directory_iterator(passes)) {
        if (!fs::is_directory(pass.path() / "shaders")) continue;
        for (const auto& f : fs::directory_iterator(pass.path() / "shaders")) {
            if (!stages.count(f.path().extension().string())) continue;
            ++entryPoints;
            const std::string name = pass.path().filename().string() + "/" + f.path().filename().string();
            EXPECT_TRUE(used.count(name)) << fs::relative(f.path(), passes.parent_path()).generic_string()
                                          << " is not used by any pass pipeline";
        }
    }
    EXPECT_GT(entryPoints, 20);
}

// The recorder reads real layouts, not empty ones: the forward trace binds the scene in set 0 and its
// pass bindings in set 1 (passes/caustic_maps/caustic_resources.cpp).
TEST(BindingTruth, RecordedForwardTraceHasSceneAndPassLayouts) {
    auto recorded = recordPassPipelines({true});
    ASSERT_TRUE(recorded.ok()) << recorded.message();
    const RecordedPipeline* forward = nullptr;
    for (const auto& p : recorded.value())
        if (p.debugName == "forward_trace/forward.rgen") forward = &p;
    ASSERT_NE(forward, nullptr);
    ASSERT_EQ(forward->layouts.size(), 2u);
    EXPECT_EQ(forward->layouts[0].items.front().type, rhi::BindingType::AccelStruct);
    EXPECT_FALSE(forward->layouts[1].items.empty());
    EXPECT_GT(forward->pushConstantBytes, 0u);
    EXPECT_GT(forward->maxPayloadBytes, 0u);
}

}  // namespace
}  // namespace caustics::test
