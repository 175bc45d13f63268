// Text checks of the D3D12 HLSL (no DXC here to compile it): every GLSL entry point has an HLSL
// counterpart (a pass's own passes/<pass>/shaders/<x>.<stage> beside <x>.hlsl, docs/shaders.md; the
// others under shaders/vulkan/<path> and shaders/d3d12/<path>.hlsl), embedded and self-contained,
// declaring the `main` entry point of its stage, and every resource names its register space.
#include <gtest/gtest.h>

#include <filesystem>
#include <map>
#include <string>

#include "caustics/hlsl_sources.h"

namespace fs = std::filesystem;

namespace caustics::hlsl {
namespace {

const fs::path kShaders = fs::path(CAUSTICS_SOURCE_DIR) / "shaders";
const fs::path kPasses = fs::path(CAUSTICS_SOURCE_DIR) / "passes";

// GLSL stage extension -> what the HLSL must declare for it.
const std::map<std::string, std::string>& stageMarkers() {
    static const std::map<std::string, std::string> m = {
        {".vert", "SV_Position"},
        {".frag", "SV_Target"},
        {".comp", "[numthreads("},
        {".rgen", "[shader(\"raygeneration\")]"},
        {".rchit", "[shader(\"closesthit\")]"},
        {".rahit", "[shader(\"anyhit\")]"},
        {".rmiss", "[shader(\"miss\")]"},
        {".rint", "[shader(\"intersection\")]"},
        {".rcall", "[shader(\"callable\")]"},
    };
    return m;
}

bool isStage(const fs::path& p) { return stageMarkers().count(p.extension().string()) != 0; }

// A pass's own GLSL entries: passes/<pass>/shaders/<x>.<stage>, named "<pass>/<x>.<stage>".
std::vector<fs::path> ownGlslFiles() {
    std::vector<fs::path> out;
    for (const auto& pass : fs::directory_iterator(kPasses))
        if (fs::is_directory(pass.path() / "shaders"))
            for (const auto& e : fs::directory_iterator(pass.path() / "shaders"))
                if (e.is_regular_file() && isStage(e.path())) out.push_back(e.path());
    return out;
}

std::vector<std::string> glslEntryPoints() {
    std::vector<std::string> out;
    for (const auto& e : fs::recursive_directory_iterator(kShaders / "vulkan"))
        if (e.is_regular_file() && isStage(e.path()))
            out.push_back(fs::relative(e.path(), kShaders / "vulkan").generic_string());
    for (const fs::path& f : ownGlslFiles())
        out.push_back(f.parent_path().parent_path().filename().string() + "/" + f.filename().string());
    return out;
}

TEST(HlslSources, EveryGlslEntryPointHasAnHlslFileWithTheSameStem) {
    const auto entries = glslEntryPoints();
    ASSERT_FALSE(entries.empty());
    for (const auto& e : fs::recursive_directory_iterator(kShaders / "vulkan"))
        if (e.is_regular_file() && isStage(e.path())) {
            const std::string rel = fs::relative(e.path(), kShaders / "vulkan").generic_string();
            EXPECT_TRUE(fs::exists(kShaders / "d3d12" / (rel + ".hlsl"))) << "missing shaders/d3d12/" << rel << ".hlsl";
        }
    for (const fs::path& f : ownGlslFiles()) {
        fs::path hlsl = f;
        hlsl.replace_extension(".hlsl");
        EXPECT_TRUE(fs::exists(hlsl)) << "missing " << fs::relative(hlsl, kPasses.parent_path()).generic_string();
    }
}

TEST(HlslSources, EveryGlslEntryPointIsEmbedded) {
    for (const std::string& e : glslEntryPoints()) EXPECT_FALSE(source(e).empty()) << e;
}

TEST(HlslSources, EachShaderDeclaresMainForItsStage) {
    for (const std::string& e : glslEntryPoints()) {
        const std::string_view text = source(e);
        const std::string& marker = stageMarkers().at(fs::path(e).extension().string());
        EXPECT_NE(text.find(marker), std::string_view::npos) << e << " lacks " << marker;
        EXPECT_NE(text.find(" main("), std::string_view::npos) << e << " has no main()";
    }
}

TEST(HlslSources, EmbeddedTextHasNoQuotedIncludesLeft) {
    for (std::string_view name : names()) {
        const std::string_view text = source(name);
        EXPECT_EQ(text.find("#include \""), std::string_view::npos) << name;
        EXPECT_NE(text.find("#line 1 "), std::string_view::npos) << name;   // messages map to the files
    }
}

TEST(HlslSources, EveryRegisterNamesItsSpace) {
    // docs/d3d12.md: binding layout i -> space i, push constants space999, draw parameters space998.
    for (std::string_view name : names()) {
        const std::string_view text = source(name);
        for (size_t at = text.find("register("); at != std::string_view::npos; at = text.find("register(", at + 1)) {
            const size_t close = text.find(')', at);
            const std::string_view reg = text.substr(at, close - at);
            // Every register is generated from a binding declaration, which names its space.
            const bool named = reg.find("space") != std::string_view::npos;
            EXPECT_TRUE(named) << name << ": " << reg;
        }
    }
}

TEST(HlslSources, PushConstantsUseSpace999) {
    for (std::string_view name : names()) {
        const std::string_view text = source(name);
        const size_t at = text.find("ConstantBuffer<Push>");
        if (at == std::string_view::npos) continue;
        EXPECT_NE(text.substr(at, 80).find("register(b0, space999)"), std::string_view::npos) << name;
    }
}

TEST(HlslSources, LookupAcceptsTheSuffixAndRejectsUnknownNames) {
    EXPECT_EQ(source("composite/composite.comp"), source("composite/composite.comp.hlsl"));
    EXPECT_TRUE(source("composite/nothing.comp").empty());
}

TEST(HlslSources, ShaderCodeIsHlslNamedAfterTheFile) {
    rhi::ShaderCode code = shaderCode("composite/composite.comp");
    EXPECT_EQ(code.kind, rhi::ShaderCodeKind::HLSL);
    EXPECT_EQ(code.debugName, "composite/composite.comp.hlsl");
    EXPECT_EQ(code.bytes.size(), source("composite/composite.comp").size());
}

}  // namespace
}  // namespace caustics::hlsl
