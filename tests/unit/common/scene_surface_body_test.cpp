// The scene API's shared-dialect functions (shaders/common/scene.h, camera_constants.h;
// docs/shaders.md, "Scene API") compiled as C++: the surface a ray hit reports, and the camera's
// projection and its inverse, as every pass's shaders compute them.
#include <gtest/gtest.h>

#include <vector>

#include <glm/gtc/matrix_transform.hpp>

#include "common/camera.h"
#include "common/scene.h"

namespace caustics::shader {

namespace {
// A one-triangle scene: the scene shim's buffers (bindings of caustics::SceneBindings on the GPU).
std::vector<float3> gPositions = {float3(0.0f), float3(1.0f, 0.0f, 0.0f), float3(0.0f, 0.0f, -1.0f)};
std::vector<uint> gIndices = {0u, 1u, 2u};
std::vector<GpuVertex> gVertices(3);
std::vector<GpuMaterial> gMaterials(1);
std::vector<GpuInstance> gInstances(1);
}  // namespace
GpuInstance sceneInstance(uint i) { return gInstances.at(i); }
GpuVertex sceneVertex(uint i) { return gVertices.at(i); }
GpuMaterial sceneMaterial(uint i) { return gMaterials.at(i); }
uint sceneIndex(uint i) { return gIndices.at(i); }
float3 scenePosition(uint vertex) { return gPositions.at(vertex); }
float3 sceneBaseColor(GpuMaterial m, float2) { return m.baseColor; }

namespace {

void placeTriangle(const float4x4& objectToWorld) {
    for (uint i = 0; i < 3u; ++i) {
        gVertices[i].normal = float3(0.0f, 1.0f, 0.0f);
        gVertices[i].u = float(i == 1u);
        gVertices[i].v = float(i == 2u);
    }
    gMaterials[0].baseColor = float3(0.25f, 0.5f, 0.75f);
    gMaterials[0].flags = kMaterialSpecular | kMaterialThinWalled;
    gInstances[0].objectToWorld = objectToWorld;
    gInstances[0].normalToWorld = glm::transpose(glm::inverse(objectToWorld));
}

// Bounds 1e-6: float products of a few terms of order 1, measured 0 here and 4.4e-8 for the rotation below.
TEST(SceneSurfaceBody, HitIsTheBarycentricPointOfTheTransformedTriangle) {
    placeTriangle(glm::translate(float4x4(1.0f), float3(1.0f, 2.0f, 3.0f)) *
                  glm::scale(float4x4(1.0f), float3(2.0f, 1.0f, 1.0f)));
    SurfaceHit h = sceneSurfaceHit(0u, 0u, float2(0.25f, 0.5f));
    // Object point 0.25 x (1, 0, 0) + 0.5 x (0, 0, -1), scaled x2 in x, moved by (1, 2, 3).
    EXPECT_NEAR(glm::distance(h.position, float3(1.5f, 2.0f, 2.5f)), 0.0f, 1e-6f);
    // The winding (p1 - p0) x (p2 - p0) = (1, 0, 0) x (0, 0, -1) = (0, 1, 0); non-uniform scale keeps it.
    EXPECT_NEAR(glm::distance(h.geometricNormal, float3(0.0f, 1.0f, 0.0f)), 0.0f, 1e-6f);
    EXPECT_NEAR(glm::distance(h.shadingNormal, float3(0.0f, 1.0f, 0.0f)), 0.0f, 1e-6f);
    EXPECT_EQ(h.uv, float2(0.25f, 0.5f));
    EXPECT_EQ(h.objectId, 1u);   // instance index + 1, as the G-buffer stores it
    EXPECT_EQ(h.baseColor, gMaterials[0].baseColor);
    EXPECT_TRUE(h.optics.thinWalled);
    EXPECT_TRUE(sceneMaterialIsSpecular(h.material));
}

TEST(SceneSurfaceBody, ShadingNormalFallsBackToTheGeometricOneWhereVerticesHaveNone) {
    placeTriangle(glm::rotate(float4x4(1.0f), 0.5f * kPi, float3(1.0f, 0.0f, 0.0f)));
    for (GpuVertex& v : gVertices) v.normal = float3(0.0f);
    SurfaceHit h = sceneSurfaceHit(0u, 0u, float2(0.3f, 0.3f));
    EXPECT_EQ(h.shadingNormal, h.geometricNormal);
    EXPECT_NEAR(glm::distance(h.geometricNormal, float3(0.0f, 0.0f, 1.0f)), 0.0f, 1e-6f);   // +y turned to +z
}

CameraConstants camera() {
    CameraConstants c{};
    c.eye = float4(0.0f, 1.0f, 5.0f, 0.25f);        // w: jitter x (pixels)
    c.forward = float4(0.0f, 0.0f, -1.0f, 0.5f);    // w: tan(fovY / 2)
    c.right = float4(1.0f, 0.0f, 0.0f, 2.0f);       // w: aspect
    c.up = float4(0.0f, 1.0f, 0.0f, -0.5f);         // w: jitter y (pixels)
    c.frame = uint4(200u, 100u, 0u, 0u);
    return c;
}

// cameraProject inverts cameraPixelDirection / cameraWorldPosition, the jitter included. Bounds 1e-5 m,
// 1e-4 px, 1e-6: float round trips of order-1 values, measured 0 for each.
TEST(SceneSurfaceBody, CameraProjectionAndItsInverseAgreeWithTheJitter) {
    const CameraConstants c = camera();
    const float2 pixel(37.5f, 81.25f);
    const float3 x = cameraWorldPosition(c, pixel, 3.0f);   // 3 m along the optical axis
    EXPECT_NEAR(5.0f - x.z, 3.0f, 1e-5f);
    CameraProjection p = cameraProject(c, x);
    ASSERT_TRUE(p.valid);
    EXPECT_NEAR(p.pixel.x, pixel.x, 1e-4f);
    EXPECT_NEAR(p.pixel.y, pixel.y, 1e-4f);
    EXPECT_NEAR(p.depth, 3.0f, 1e-5f);
    // The image centre plus the jitter is on the optical axis.
    EXPECT_NEAR(glm::distance(cameraPixelDirection(c, float2(100.25f, 49.5f)), float3(0.0f, 0.0f, -1.0f)), 0.0f, 1e-6f);
    EXPECT_FALSE(cameraProject(c, float3(0.0f, 1.0f, 6.0f)).valid);   // behind the eye
}

}  // namespace
}  // namespace caustics::shader
