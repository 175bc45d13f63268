// "atrium (Sponza stand-in, generated)": a two-storey colonnaded courtyard about the size of the
// Khronos Sponza (25 x 16 x 11.5 m) and about as heavy (~260k triangles; Sponza has ~262k), with the
// caustic objects of the table scene standing in the middle of the court at 4x scale. Geometry of one
// material is merged into one mesh (one BLAS), as Sponza's few large meshes are.
#include <glm/gtc/matrix_transform.hpp>

#include "caustics/scene/builtin_scenes.h"
#include "caustics/scene/mesh_builder.h"
#include "caustics/scene/mesh_utils.h"
#include "caustics/scene/procedural_textures.h"
#include "scene_build.h"

namespace caustics::scene {

using namespace build;

namespace {

constexpr float kHalfX = 12.5f, kHalfZ = 8.0f;   // outer walls
constexpr float kCourtZ = 5.0f;                 // colonnade line
constexpr float kStorey = 6.0f, kTop = 11.5f;
constexpr int kColumnsPerRow = 12;
constexpr float kColumnSpacing = 2.0f;

glm::mat4 translate(float x, float y, float z) { return glm::translate(glm::mat4(1.0f), {x, y, z}); }

// A column standing at y = 0: torus base, tessellated shaft, flared capital with an abacus.
Mesh makeColumn(float height) {
    Mesh col;
    const float r = 0.3f;
    appendMesh(col, makeBox({0.42f, 0.1f, 0.42f}), translate(0, 0.1f, 0));               // plinth
    appendMesh(col, makeTorus(r + 0.02f, 0.07f, 48, 8), translate(0, 0.27f, 0));        // base moulding
    appendMesh(col, makeCylinder(r, height - 0.9f, 48, 20, false), translate(0, 0.2f, 0)); // shaft
    appendMesh(col, makeTorus(r + 0.01f, 0.05f, 48, 8), translate(0, height - 0.7f, 0)); // necking
    Mesh bell = makeCylinder(r, 0.45f, 48, 6, false);
    for (glm::vec3& p : bell.positions) {   // flare the capital's bell outwards towards the top
        float t = p.y / 0.45f;
        p.x *= 1.0f + 0.45f * t * t;
        p.z *= 1.0f + 0.45f * t * t;
    }
    appendMesh(col, bell, translate(0, height - 0.65f, 0));
    appendMesh(col, makeBox({0.48f, 0.1f, 0.48f}), translate(0, height - 0.1f, 0));     // abacus
    return col;
}

}  // namespace

Scene makeAtriumScene() {
    Scene scene;
    scene.name = "atrium (Sponza stand-in, generated)";
    scene.isStandIn = true;
    uint32_t tileTex = addTexture(scene, makeTileTexture(128, {0.55f, 0.45f, 0.35f}, {0.25f, 0.22f, 0.2f}, 4, 0.12f, 11), "floor tiles");
    uint32_t stoneTex = addTexture(scene, makeNoiseTexture(64, {0.70f, 0.66f, 0.58f}, 0.2f, 5), "stone");
    uint32_t plasterTex = addTexture(scene, makeNoiseTexture(64, {0.72f, 0.60f, 0.48f}, 0.12f, 9), "plaster");
    uint32_t floorMat = addMaterial(scene, diffuse("floor tiles", glm::vec3(1.0f), int32_t(tileTex), 0.7f));
    uint32_t stoneMat = addMaterial(scene, diffuse("stone", glm::vec3(1.0f), int32_t(stoneTex), 0.85f));
    uint32_t wallMat = addMaterial(scene, diffuse("plaster walls", glm::vec3(1.0f), int32_t(plasterTex), 0.9f));

    // Floor (tiles 0.5 m: uvScale 0.5 repeats the 4-tile texture every 2 m) and the upper floor /
    // balcony slabs over the galleries, the roof of the upper gallery.
    Mesh floor = makePlane(kHalfX, kHalfZ, 100, 0.5f);
    Mesh walls;
    for (float side : {-1.0f, 1.0f}) {
        float zMid = side * 0.5f * (kHalfZ + kCourtZ), zHalf = 0.5f * (kHalfZ - kCourtZ) + 0.3f;
        appendMesh(floor, makePlane(kHalfX, zHalf, 24, 0.5f), translate(0, kStorey + 0.25f, zMid));   // balcony walk
        appendMesh(walls, makeBox({kHalfX, 0.125f, zHalf}, 0.5f), translate(0, kStorey, zMid));        // slab
        appendMesh(walls, makeBox({kHalfX, 0.15f, zHalf}, 0.5f), translate(0, kTop, zMid));            // roof
        // Outer long walls, subdivided so they light smoothly in rasterized G-buffers.
        Mesh wall = makePlane(kHalfX, kTop * 0.5f, 40, 0.5f);
        glm::mat4 stand = translate(0, kTop * 0.5f, side * kHalfZ) *
                          glm::rotate(glm::mat4(1.0f), glm::radians(side * -90.0f), {1, 0, 0});   // faces the court
        appendMesh(walls, wall, stand);
        // End walls.
        Mesh end = makePlane(kHalfZ, kTop * 0.5f, 30, 0.5f);
        glm::mat4 endStand = translate(side * kHalfX, kTop * 0.5f, 0) *
                             glm::rotate(glm::mat4(1.0f), glm::radians(side * 90.0f), {0, 0, 1}) *
                             glm::rotate(glm::mat4(1.0f), glm::radians(90.0f), {0, 1, 0});
        appendMesh(walls, end, endStand);
    }

    // Colonnades: two storeys on both long sides, arches between neighbouring columns.
    Mesh stone;
    Mesh lower = makeColumn(4.6f), upper = makeColumn(3.6f);
    Mesh arch = makeArch(kColumnSpacing - 0.6f, 1.3f, 0.6f, 24);
    Mesh baluster = makeCylinder(0.05f, 0.8f, 12, 3, true);
    for (float side : {-1.0f, 1.0f}) {
        float z = side * kCourtZ;
        for (int i = 0; i < kColumnsPerRow; ++i) {
            float x = (float(i) - 0.5f * float(kColumnsPerRow - 1)) * kColumnSpacing;
            appendMesh(stone, lower, translate(x, 0.0f, z));
            appendMesh(stone, upper, translate(x, kStorey + 0.25f, z));
            if (i + 1 < kColumnsPerRow) {
                appendMesh(stone, arch, translate(x + 0.5f * kColumnSpacing, 4.6f, z));
                appendMesh(stone, arch, translate(x + 0.5f * kColumnSpacing, kStorey + 0.25f + 3.6f, z));
            }
        }
        // Balcony balustrade: balusters every 0.25 m and a hand rail.
        for (float x = -11.0f; x <= 11.0f; x += 0.25f) appendMesh(stone, baluster, translate(x, kStorey + 0.25f, z));
        appendMesh(stone, makeBox({11.2f, 0.06f, 0.1f}), translate(0, kStorey + 1.1f, z));
    }

    addObject(scene, std::move(floor), floorMat, "floor");
    addObject(scene, std::move(walls), wallMat, "walls and slabs");
    addObject(scene, std::move(stone), stoneMat, "colonnades");

    CausticPlacement placement;
    placement.origin = {0.0f, 0.0f, 0.0f};
    placement.scale = 4.0f;
    placement.thirdLightPosition = {-6.0f, 8.0f, -2.0f};
    placement.thirdLightTarget = {-kHalfX + 0.1f, 10.5f, -kHalfZ + 0.1f};   // far upper corner
    addCausticObjects(scene, placement);
    scene.lights.back().intensity = 200.0f;   // ~8 m throw: ~3 lx on the corner
    scene.lights.back().outerConeAngle = 0.3f;
    scene.lights.back().innerConeAngle = 0.22f;
    scene.cameras.push_back(lookAt({-3.5f, 1.8f, 3.6f}, {0.2f, 0.2f, 0.0f}, glm::radians(55.0f)));
    scene.cameras.push_back(lookAt({-10.0f, 8.0f, 3.0f}, {6.0f, 3.0f, -2.0f}, glm::radians(60.0f)));
    sortTrianglesMorton(scene);
    return scene;
}

}  // namespace caustics::scene
