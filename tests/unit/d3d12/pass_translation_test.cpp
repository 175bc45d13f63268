// D3D12 translation of every pass pipeline, device-free: the passes are created on a recording device
// (tests/unit/bindings/pass_pipeline_recorder.h) and each pipeline's root signature, state object and
// shader tables are translated as the D3D12 backend does before calling the runtime. Both caustic
// shader variants (float atomics / fixed point) are covered.
#include <set>

#include <gtest/gtest.h>

#include "graphics_pipeline_desc.h"
#include "pass_pipeline_recorder.h"
#include "root_signature_layout.h"
#include "shader_table_image.h"
#include "state_object_builder.h"

namespace caustics::rhi::d3d12 {
namespace {

using test::PipelineKind;
using test::RecordedPipeline;

std::vector<RecordedPipeline> everyPassPipeline() {
    std::vector<RecordedPipeline> all;
    // Float atomics; fixed point in uint32 words; fixed point in uint64 words (docs/caustics.md "Fixed point").
    for (auto [floatAtomics, int64Atomics] : {std::pair{true, false}, std::pair{false, false}, std::pair{false, true}}) {
        auto recorded = test::recordPassPipelines({floatAtomics, int64Atomics});
        EXPECT_TRUE(recorded.ok()) << (recorded.ok() ? "" : recorded.message());
        if (recorded.ok()) all.insert(all.end(), recorded.value().begin(), recorded.value().end());
    }
    return all;
}

class PassTranslation : public ::testing::Test {
protected:
    static void SetUpTestSuite() { pipelines = new std::vector<RecordedPipeline>(everyPassPipeline()); }
    static void TearDownTestSuite() { delete pipelines; }
    static std::vector<RecordedPipeline>* pipelines;
};
std::vector<RecordedPipeline>* PassTranslation::pipelines = nullptr;

TEST_F(PassTranslation, RecordsEveryPassOfTheModule) {
    std::set<std::string> names;
    for (const auto& p : *pipelines) names.insert(p.debugName);
    // G-buffer, direct lighting, composite, caustic maps, forward (float + fixed), backward, gather,
    // resolve, temporal, variance, a-trous weights, a-trous, history.
    EXPECT_GE(names.size(), 12u);
    int rayTracing = 0, graphics = 0, compute = 0;
    for (const auto& p : *pipelines)
        (p.kind == PipelineKind::RayTracing ? rayTracing : p.kind == PipelineKind::Graphics ? graphics : compute)++;
    EXPECT_GE(rayTracing, 8);   // direct, forward, backward, gather; twice
    EXPECT_GE(graphics, 4);     // G-buffer, caustic maps; twice
    EXPECT_GE(compute, 10);     // composite and the six filter/resolve kernels; twice
}

// Every binding becomes a descriptor range in register space = layout index, register = slot, of
// the class its type needs; push constants become root constants b0, space999.
TEST_F(PassTranslation, EveryRootSignatureMapsEachBindingToItsRegisterAndSpace) {
    for (const auto& p : *pipelines) {
        SCOPED_TRACE(p.debugName);
        auto kind = p.kind == PipelineKind::Graphics ? RootSignatureKind::Graphics : RootSignatureKind::Compute;
        auto layout = rootSignatureLayoutFromBindings(p.layouts, p.pushConstantBytes, kind);
        ASSERT_TRUE(layout.ok()) << layout.message();
        const RootSignatureLayout& rs = layout.value();
        for (uint32_t space = 0; space < p.layouts.size(); ++space) {
            for (const BindingLayoutItem& item : p.layouts[space].items) {
                const RegisterClass cls = registerClassOf(item.type);
                const int32_t param = cls == RegisterClass::Sampler ? rs.samplerTableParameter[space]
                                                                     : rs.resourceTableParameter[space];
                ASSERT_GE(param, 0) << "space " << space << " slot " << item.slot;
                bool found = false;
                for (const RootDescriptorRange& r : rs.parameters[size_t(param)].ranges)
                    found |= r.registerClass == cls && r.space == space && r.baseRegister == item.slot &&
                             r.count == item.arraySize;
                EXPECT_TRUE(found) << registerLetter(cls) << item.slot << ", space" << space << " has no range";
            }
        }
        if (p.pushConstantBytes > 0) {
            ASSERT_GE(rs.pushConstantParameter, 0);
            const RootParameterLayout& push = rs.parameters[size_t(rs.pushConstantParameter)];
            EXPECT_EQ(push.registerSpace, kPushConstantSpace);
            EXPECT_EQ(push.shaderRegister, 0u);
            EXPECT_EQ(push.num32BitValues, p.pushConstantBytes / 4);
        }
        RootSignatureDescStorage storage(rs);
        EXPECT_EQ(storage.desc().Version, D3D_ROOT_SIGNATURE_VERSION_1_1);
        EXPECT_EQ(storage.desc().Desc_1_1.NumParameters, rs.parameters.size());
    }
}

TEST_F(PassTranslation, EveryStateObjectBuildsWithThePassPayloadAndRecursion) {
    for (const auto& p : *pipelines) {
        if (p.kind != PipelineKind::RayTracing) continue;
        SCOPED_TRACE(p.debugName);
        const std::vector<uint8_t> dxil = {0x44, 0x58, 0x42, 0x43};   // stands in for compiled DXIL
        StateObjectInputs inputs;
        for (size_t i = 0; i < p.stateObject.libraries.size(); ++i) inputs.libraryBytecode.push_back(dxil);
        inputs.globalRootSignature = reinterpret_cast<ID3D12RootSignature*>(uintptr_t(0x1000));
        StateObjectBuilder builder;
        Status built = builder.build(p.stateObject, inputs);
        ASSERT_TRUE(built.ok()) << built.message();
        int libraries = 0, hitGroups = 0;
        const D3D12_RAYTRACING_SHADER_CONFIG* config = nullptr;
        const D3D12_RAYTRACING_PIPELINE_CONFIG* pipelineConfig = nullptr;
        for (const D3D12_STATE_SUBOBJECT& s : builder.subobjects()) {
            if (s.Type == D3D12_STATE_SUBOBJECT_TYPE_DXIL_LIBRARY) ++libraries;
            if (s.Type == D3D12_STATE_SUBOBJECT_TYPE_HIT_GROUP) ++hitGroups;
            if (s.Type == D3D12_STATE_SUBOBJECT_TYPE_RAYTRACING_SHADER_CONFIG)
                config = static_cast<const D3D12_RAYTRACING_SHADER_CONFIG*>(s.pDesc);
            if (s.Type == D3D12_STATE_SUBOBJECT_TYPE_RAYTRACING_PIPELINE_CONFIG)
                pipelineConfig = static_cast<const D3D12_RAYTRACING_PIPELINE_CONFIG*>(s.pDesc);
        }
        EXPECT_EQ(libraries, int(p.stateObject.libraries.size()));
        EXPECT_EQ(hitGroups, int(p.stateObject.hitGroups.size()));
        ASSERT_NE(config, nullptr);
        EXPECT_EQ(config->MaxPayloadSizeInBytes, p.maxPayloadBytes);
        EXPECT_EQ(config->MaxAttributeSizeInBytes, p.maxAttributeBytes);
        ASSERT_NE(pipelineConfig, nullptr);
        EXPECT_EQ(pipelineConfig->MaxTraceRecursionDepth, p.stateObject.maxRecursionDepth);
        // Every record of every shader table the pass creates names something the state object exports.
        const auto& names = builder.shaderTableNames();
        for (const ShaderTableDesc& table : p.shaderTables) {
            std::vector<const ShaderRecord*> records = {&table.rayGen};
            for (const auto* list : {&table.missRecords, &table.hitGroupRecords, &table.callableRecords})
                for (const ShaderRecord& r : *list) records.push_back(&r);
            for (const ShaderRecord* r : records)
                EXPECT_NE(std::find(names.begin(), names.end(), r->exportName), names.end()) << r->exportName;
        }
    }
}

// Each record starts with its export's 32-byte identifier at a 32-byte aligned offset in a region
// aligned to 64 (D3D12 shader table rules), in the order the pass listed them.
TEST_F(PassTranslation, EveryShaderTableImagePlacesEachIdentifierAtItsRecord) {
    int tables = 0;
    for (const auto& p : *pipelines) {
        for (const ShaderTableDesc& table : p.shaderTables) {
            SCOPED_TRACE(p.debugName);
            ++tables;
            std::vector<std::string> order = {table.rayGen.exportName};
            auto identifier = [&](const std::string& name) {
                auto it = std::find(order.begin(), order.end(), name);
                if (it == order.end()) it = order.insert(order.end(), name);
                return std::vector<uint8_t>(D3D12_SHADER_IDENTIFIER_SIZE_IN_BYTES, uint8_t(1 + (it - order.begin())));
            };
            auto image = buildShaderTableImage(table, p.stateObject.localBindings.localDataBytes, identifier);
            ASSERT_TRUE(image.ok()) << image.message();
            const ShaderTableLayout& l = image.value().layout;
            auto expectRecord = [&](const ShaderTableRegion& region, uint32_t index, const std::string& name) {
                const uint64_t offset = region.offset + region.stride * index;
                EXPECT_EQ(region.offset % D3D12_RAYTRACING_SHADER_TABLE_BYTE_ALIGNMENT, 0u);
                EXPECT_EQ(region.stride % D3D12_RAYTRACING_SHADER_RECORD_BYTE_ALIGNMENT, 0u);
                EXPECT_EQ(image.value().bytes[offset], identifier(name)[0]) << name;
            };
            expectRecord(l.rayGen, 0, table.rayGen.exportName);
            for (uint32_t i = 0; i < table.missRecords.size(); ++i) expectRecord(l.miss, i, table.missRecords[i].exportName);
            for (uint32_t i = 0; i < table.hitGroupRecords.size(); ++i)
                expectRecord(l.hitGroup, i, table.hitGroupRecords[i].exportName);
        }
    }
    EXPECT_GE(tables, 8);
}

TEST_F(PassTranslation, EveryGraphicsPipelineTranslatesToAPsoDesc) {
    for (const auto& p : *pipelines) {
        if (p.kind != PipelineKind::Graphics) continue;
        SCOPED_TRACE(p.debugName);
        auto pso = GraphicsPsoDescStorage::create(p.graphics);
        ASSERT_TRUE(pso.ok()) << pso.message();
        EXPECT_EQ(pso.value()->desc().NumRenderTargets, p.graphics.colorFormats.size());
        EXPECT_EQ(pso.value()->desc().RasterizerState.CullMode, toCullMode(p.graphics.cullMode));
    }
}

}  // namespace
}  // namespace caustics::rhi::d3d12
