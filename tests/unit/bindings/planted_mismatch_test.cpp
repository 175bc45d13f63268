// The binding check fails on one changed binding, on either side: each test plants one mismatch in
// an in-memory copy of the forward trace (its shader text or its C++ desc) and expects the checker
// to name it. Unchanged, the same pipeline passes (BindingTruth tests).
#include <regex>

#include <gtest/gtest.h>

#include "binding_checker.h"

namespace caustics::test {
namespace {

class PlantedMismatch : public ::testing::Test {
protected:
    void SetUp() override {
        auto recorded = recordPassPipelines({true});
        ASSERT_TRUE(recorded.ok()) << recorded.message();
        for (auto& p : recorded.value())
            if (p.debugName == "forward_trace/forward.rgen") forward = p;
        ASSERT_EQ(forward.debugName, "forward_trace/forward.rgen");
    }

    // Checks the forward trace with the first match of `pattern` in `file` (HLSL: the embedded text of
    // the ray-generation shader; GLSL: a file the entry includes, e.g. its generated bindings) replaced
    // by `replacement`.
    std::vector<std::string> checkWithEdit(ShaderLanguage language, const std::string& file, const std::string& pattern,
                                           const std::string& replacement) {
        bool edited = false;
        auto edit = [&](const std::string& text) {
            std::string changed = std::regex_replace(text, std::regex(pattern), replacement,
                                                     std::regex_constants::format_first_only);
            edited = edited || changed != text;
            return changed;
        };
        RecordedPipeline planted = forward;
        IncludeReader files = [&](const std::string& path) -> std::optional<std::string> {
            std::optional<std::string> text = readTextFile(path);
            if (text && path.size() >= file.size() && path.compare(path.size() - file.size(), file.size(), file) == 0)
                text = edit(*text);
            return text;
        };
        if (language == ShaderLanguage::Hlsl)
            for (RecordedShader& s : planted.shaders)
                if (s.name == file) s.hlsl = edit(s.hlsl);
        auto errors = checkPipelineBindings(planted, language, CAUSTICS_SOURCE_DIR, files);
        EXPECT_TRUE(edited) << "the planted edit did not apply: " << file << " " << pattern;
        return errors;
    }

    std::vector<std::string> check(ShaderLanguage language) {
        return checkPipelineBindings(forward, language, CAUSTICS_SOURCE_DIR);
    }

    // A change on the C++ side disagrees with the GLSL and with the HLSL.
    void expectReportedForBothLanguages(const std::string& text) {
        for (auto language : {ShaderLanguage::Glsl, ShaderLanguage::Hlsl}) {
            auto errors = check(language);
            EXPECT_TRUE(anyContains(errors, text)) << ::testing::PrintToString(errors);
        }
    }

    static bool anyContains(const std::vector<std::string>& errors, const std::string& text) {
        for (const auto& e : errors)
            if (e.find(text) != std::string::npos) return true;
        return false;
    }

    RecordedPipeline forward;
};

TEST_F(PlantedMismatch, UnchangedForwardTracePasses) {
    for (auto language : {ShaderLanguage::Glsl, ShaderLanguage::Hlsl})
        EXPECT_TRUE(check(language).empty()) << ::testing::PrintToString(check(language));
}

TEST_F(PlantedMismatch, HlslRegisterNumberMovedIsReported) {
    // The hits buffer (u6, space1) moved to u12, a register the C++ layout does not have.
    auto errors = checkWithEdit(ShaderLanguage::Hlsl, "forward_trace/forward.rgen", "register\\(u6, space1\\)", "register(u12, space1)");
    EXPECT_TRUE(anyContains(errors, "'hits' (space 1, slot 12, StorageBufferRW)")) << ::testing::PrintToString(errors);
    EXPECT_TRUE(anyContains(errors, "has no slot 12"));
}

TEST_F(PlantedMismatch, HlslRegisterSpaceChangedIsReported) {
    auto errors = checkWithEdit(ShaderLanguage::Hlsl, "forward_trace/forward.rgen", "register\\(u6, space1\\)", "register(u6, space0)");
    EXPECT_TRUE(anyContains(errors, "'hits' (space 0, slot 6, StorageBufferRW)")) << ::testing::PrintToString(errors);
}

TEST_F(PlantedMismatch, HlslRegisterClassOfTheWrongTypeIsReported) {
    auto errors = checkWithEdit(ShaderLanguage::Hlsl, "forward_trace/forward.rgen", "RWByteAddressBuffer hits : register\\(u6",
                                "RWByteAddressBuffer hits : register(t6");
    EXPECT_TRUE(anyContains(errors, "cannot live in register class t")) << ::testing::PrintToString(errors);
}

TEST_F(PlantedMismatch, GlslBindingNumberChangedIsReported) {
    // The forward pass's GLSL declarations are generated (forward_bindings.h -> bindings/forward.h).
    auto errors = checkWithEdit(ShaderLanguage::Glsl, "bindings/forward.h", "binding = 6, std430\\) buffer hitsBuffer",
                                "binding = 2, std430) buffer hitsBuffer");
    // Slot 2 exists in the C++ layout but holds another kind of binding than the writable hit buffer.
    EXPECT_TRUE(anyContains(errors, "'hitsBuffer' (set 1, slot 2, StorageBufferRW): the C++ layout 1 declares slot 2 as"))
        << ::testing::PrintToString(errors);
}

TEST_F(PlantedMismatch, CppBindingTypeChangedIsReportedOnBothSides) {
    for (auto& item : forward.layouts[1].items)
        if (item.slot == 6) item.type = rhi::BindingType::StorageBufferRO;
    expectReportedForBothLanguages("declares slot 6 as StorageBufferRO");
}

TEST_F(PlantedMismatch, CppPushConstantSizeChangedIsReportedOnBothSides) {
    forward.pushConstantBytes += 4;
    expectReportedForBothLanguages("but C++ sets pushConstantBytes = " + std::to_string(forward.pushConstantBytes));
}

TEST_F(PlantedMismatch, CppPayloadSizeChangedIsReportedOnBothSides) {
    forward.maxPayloadBytes += 4;
    expectReportedForBothLanguages("C++ sets maxPayloadBytes = " + std::to_string(forward.maxPayloadBytes));
}

}  // namespace
}  // namespace caustics::test
