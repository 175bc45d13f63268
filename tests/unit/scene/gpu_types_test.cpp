#include <gtest/gtest.h>

#include "caustics/scene/builtin_scenes.h"
#include "caustics/scene/gpu_scene.h"
#include "caustics/scene/mesh_utils.h"

namespace caustics::scene {
namespace {

TEST(PackScene, MeshRangesConcatenateVerticesAndIndices) {
    Scene s = makeBuiltinScene("builtin");
    PackedScene p = packScene(s);
    ASSERT_EQ(p.meshRanges.size(), s.meshes.size());
    uint32_t v = 0, i = 0;
    for (size_t m = 0; m < s.meshes.size(); ++m) {
        EXPECT_EQ(p.meshRanges[m].firstVertex, v);
        EXPECT_EQ(p.meshRanges[m].firstIndex, i);
        v += uint32_t(s.meshes[m].positions.size());
        i += uint32_t(s.meshes[m].indices.size());
    }
    EXPECT_EQ(p.positions.size(), v);
    EXPECT_EQ(p.vertices.size(), v);
    EXPECT_EQ(p.indices.size(), i);
    EXPECT_EQ(p.instances.size(), s.instances.size());
    EXPECT_EQ(p.materials.size(), s.materials.size());
}

TEST(PackScene, SpecularMaterialsAndInstancesAreFlagged) {
    Scene s = makeBuiltinScene("builtin");
    PackedScene p = packScene(s);
    for (size_t m = 0; m < s.materials.size(); ++m)
        EXPECT_EQ((p.materials[m].flags & kMaterialSpecular) != 0, s.materials[m].isSpecular()) << s.materials[m].name;
    for (size_t i = 0; i < s.instances.size(); ++i) {
        EXPECT_EQ((p.instances[i].flags & kInstanceSpecular) != 0, isSpecularInstance(s, s.instances[i]));
        EXPECT_EQ(p.instances[i].objectId, s.instances[i].objectId);
    }
}

TEST(InstanceDesc, IsRowMajorWithIndexIdAndSpecularMask) {
    Scene s = makeBuiltinScene("builtin");
    for (uint32_t i = 0; i < s.instances.size(); ++i) {
        rhi::InstanceDesc d = makeInstanceDesc(s, i);
        EXPECT_EQ(d.instanceId, i);
        EXPECT_EQ(d.instanceMask, isSpecularInstance(s, s.instances[i]) ? kMaskSpecular : kMaskDiffuse);
        EXPECT_FLOAT_EQ(d.transform[0][3], s.instances[i].transform[3][0]);   // x translation
        EXPECT_FLOAT_EQ(d.transform[1][3], s.instances[i].transform[3][1]);
        EXPECT_FLOAT_EQ(d.transform[2][3], s.instances[i].transform[3][2]);
    }
}

TEST(GpuInstance, NormalMatrixIsInverseTransposeForNonUniformScale) {
    Scene s;
    s.materials.push_back({});
    s.meshes.push_back({});
    Instance inst;
    inst.transform = glm::mat4(1.0f);
    inst.transform[0][0] = 2.0f;   // scale x by 2: normals' x is scaled by 1/2
    s.instances.push_back(inst);
    GpuInstance g = toGpuInstance(s, inst, 0, 0);
    EXPECT_FLOAT_EQ(g.normalToWorld[0][0], 0.5f);
    EXPECT_FLOAT_EQ(g.normalToWorld[1][1], 1.0f);
    EXPECT_FLOAT_EQ(g.normalToWorld[3][3], 0.0f);
}

}  // namespace
}  // namespace caustics::scene
