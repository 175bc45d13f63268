// FrameInputs::hostScene: the CPU scene is checked against the host's own instance rows every frame
// (docs/embedding.md "Host scene tables"), so a host that moves its TLAS but not scene::Scene hears
// which instance differs instead of getting a caustic 39 % to 87 % too dim.
#include <gtest/gtest.h>

#include <glm/gtc/matrix_transform.hpp>

#include "caustics/host_scene.h"
#include "fake_rhi_objects.h"

namespace caustics {
namespace {

// A floor and a glass sphere stand-in: two meshes, a diffuse and a specular material.
scene::Scene twoInstances() {
    scene::Scene s;
    s.name = "two";
    s.materials.resize(2);
    s.materials[1].transmission = 1.0f;
    s.materials[1].roughness = 0.0f;
    for (uint32_t m = 0; m < 2; ++m) {
        scene::Mesh mesh;
        mesh.name = m == 0 ? "floor" : "sphere";
        mesh.positions = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}};
        mesh.normals = {{0, 0, 1}, {0, 0, 1}, {0, 0, 1}};
        mesh.indices = {0, 1, 2};
        mesh.material = m;
        s.meshes.push_back(mesh);
        s.instances.push_back({m, glm::translate(glm::mat4(1.0f), glm::vec3(0.0f, float(m), 0.0f)), m + 1});
    }
    return s;
}

// The host's tables for `scene`, with its CPU copy of the instance rows.
struct HostTables {
    std::vector<scene::GpuInstance> rows;
    HostSceneTables tables;
};

HostTables hostTablesOf(const scene::Scene& s) {
    HostTables h;
    for (const scene::Instance& inst : s.instances) h.rows.push_back(scene::toGpuInstance(s, inst, 0, 0));
    h.tables.instances = std::make_shared<rg::test::FakeBuffer>(rhi::BufferDesc()
                                                                    .setByteSize(h.rows.size() * sizeof(scene::GpuInstance))
                                                                    .setUsage(rhi::BufferUsage::Storage)
                                                                    .setDebugName("host instances"));
    h.tables.instanceRows = h.rows;
    return h;
}

TEST(HostSceneCheck, RowsThatMatchTheSceneAreAccepted) {
    scene::Scene s = twoInstances();
    HostTables h = hostTablesOf(s);
    Status st = checkHostSceneTables(h.tables, s);
    EXPECT_TRUE(st.ok()) << st.message();
}

TEST(HostSceneCheck, HostMovedAnInstanceTheSceneDidNotAndTheInstanceIsNamed) {
    scene::Scene s = twoInstances();
    HostTables h = hostTablesOf(s);
    h.rows[1].objectToWorld = glm::translate(h.rows[1].objectToWorld, glm::vec3(0.3f, 0.0f, 0.0f));   // host moved it
    Status st = checkHostSceneTables(h.tables, s);
    ASSERT_FALSE(st.ok()) << "the map frusta would follow the old position";
    EXPECT_NE(st.message().find("scene instance 1 (mesh 'sphere')"), std::string::npos) << st.message();
    EXPECT_NE(st.message().find("objectToWorld[3][0]"), std::string::npos) << st.message();
}

TEST(HostSceneCheck, FloatRoundingOfTheSameTransformIsNoDifference) {
    scene::Scene s = twoInstances();
    HostTables h = hostTablesOf(s);
    h.rows[1].objectToWorld[3][1] *= 1.0f + 1e-6f;   // a host that composes the matrix in another order
    EXPECT_TRUE(checkHostSceneTables(h.tables, s).ok());
}

TEST(HostSceneCheck, MaterialOrSpecularFlagThatDiffersIsNamed) {
    scene::Scene s = twoInstances();
    HostTables h = hostTablesOf(s);
    h.rows[0].material = 1;
    Status st = checkHostSceneTables(h.tables, s);
    ASSERT_FALSE(st.ok());
    EXPECT_NE(st.message().find("scene instance 0 (mesh 'floor')"), std::string::npos) << st.message();
    EXPECT_NE(st.message().find("material"), std::string::npos) << st.message();
    h = hostTablesOf(s);
    h.rows[1].flags = 0;
    st = checkHostSceneTables(h.tables, s);
    ASSERT_FALSE(st.ok());
    EXPECT_NE(st.message().find("specular flag"), std::string::npos) << st.message();
}

TEST(HostSceneCheck, HostTablesWithoutTheirCpuRowsAreRefused) {
    scene::Scene s = twoInstances();
    HostTables h = hostTablesOf(s);
    h.tables.instanceRows = {};
    Status st = checkHostSceneTables(h.tables, s);
    ASSERT_FALSE(st.ok()) << "nothing to check the scene against";
    EXPECT_NE(st.message().find("instanceRows holds 0 rows; the scene has 2"), std::string::npos) << st.message();
}

// docs/embedding.md "Hand-over states": the tables are imported in the state the host declares; one a
// buffer cannot be in (a render target, an acceleration structure) is refused by name.
TEST(HostSceneCheck, TablesStateABufferCannotBeHandedOverInIsRefusedNamingIt) {
    scene::Scene s = twoInstances();
    HostTables h = hostTablesOf(s);
    for (rhi::ResourceState ok : {rhi::ResourceState::ShaderResource, rhi::ResourceState::CopyDest,
                                  rhi::ResourceState::UnorderedAccess, rhi::ResourceState::AccelStructBuildInput}) {
        h.tables.tablesState = ok;
        EXPECT_TRUE(checkHostSceneTables(h.tables, s).ok()) << rhi::resourceStateName(ok);
    }
    h.tables.tablesState = rhi::ResourceState::RenderTarget;
    Status st = checkHostSceneTables(h.tables, s);
    ASSERT_FALSE(st.ok());
    EXPECT_NE(st.message().find("HostSceneTables::tablesState RenderTarget"), std::string::npos) << st.message();
}

}  // namespace
}  // namespace caustics
