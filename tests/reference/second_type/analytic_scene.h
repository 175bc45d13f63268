#pragma once
// Scenes of the independent second-type reference (docs/physics.md, "Independent second-type
// reference"): analytic solids above the diffuse floor y = 0 and one light. Nothing here uses the
// module's meshes, shaders or engine/reference: shapes are exact (spheres, boxes, capped cylinders and
// thick-walled tubes), and the optics (optics.h) are written afresh in double precision.
#include <cstdint>
#include <vector>

#include <glm/glm.hpp>

namespace caustics::optics_reference {

using Vec3 = glm::dvec3;

// A piece of a solid's boundary with its outward normal.
//   Side:   the cylinder x^2 + z^2 = radius^2 (around the axis through `centre`, vertical), y in
//           [yMin, yMax]; the outward normal points away from the axis (inward = towards it).
//   Disk:   the horizontal annulus y = yMin, rInner <= r <= radius around the axis; the outward
//           normal is +y (up) or -y.
struct Patch {
    enum class Kind { Side, Disk } kind = Kind::Side;
    double radius = 0.0, rInner = 0.0;
    double yMin = 0.0, yMax = 0.0;
    bool outwardPositive = true;  // Side: away from the axis; Disk: +y
};

struct Solid {
    enum class Kind { Sphere, Box, Patches } kind = Kind::Sphere;
    Vec3 centre{0.0};            // sphere centre, box centre, axis point (x, z) of the patches
    double radius = 0.0;         // sphere
    Vec3 halfExtent{0.0};        // box, in its own frame
    glm::dmat3 axes{1.0};        // box: columns are its local x, y, z in world space (orthonormal)
    std::vector<Patch> patches;  // Patches: a closed surface around a vertical axis
};

struct Optic {
    enum class Kind { Dielectric, Conductor } kind = Kind::Dielectric;
    double ior = 1.5;
    Vec3 sigmaA{0.0};   // 1/m inside a dielectric (Beer-Lambert)
    Vec3 f0{0.95};      // conductor: glTF 2.0 Appendix B's Schlick F0 = baseColor
    // Dielectric without a volume (glTF thin-walled, KHR_materials_volume absent): each surface is a pane
    // of two parallel faces, unbent, whose inner reflections the tracer follows one by one (use it on a
    // paneSolid, which has one surface).
    bool thinWalled = false;
};

struct Object {
    Solid solid;
    Optic optic;
};

struct Light {
    bool directional = false;
    Vec3 position{0.0};          // spot
    Vec3 direction{0.0, -1.0, 0.0};
    double intensity = 1.0;      // spot: candela; directional: lux
    double innerCone = 0.0, outerCone = 0.785398;  // KHR_lights_punctual spot angles (radians)
};

// The pinhole of the module's images (shaders/common/camera.h's convention: pixel (i, j) covers
// [i, i+1) x [j, j+1), x right, y down, the image plane at unit distance spans 2 tan(fov/2) high).
struct Pinhole {
    Vec3 eye{0.0, 1.0, 3.0}, target{0.0}, up{0.0, 1.0, 0.0};
    double verticalFov = 0.785398;
};

struct Scene {
    std::vector<Object> objects;
    Light light;
    double floorAlbedo = 0.8;    // Lambertian floor y = 0 (radiance = albedo E / pi)
};

// Solids the scenes are made of.
Solid sphereSolid(Vec3 centre, double radius);
Solid boxSolid(Vec3 centre, Vec3 halfExtent, const glm::dmat3& axes = glm::dmat3(1.0));
// A flat rectangle without thickness (a box of zero height in its frame): the surface of a thin wall.
Solid paneSolid(Vec3 centre, double halfX, double halfZ, const glm::dmat3& axes = glm::dmat3(1.0));
// Capped cylinder standing on y = yBase (axis through (axisX, axisZ)).
Solid cylinderSolid(double axisX, double axisZ, double yBase, double radius, double height);
// Thick-walled tube (outer radius, inner radius, height) standing on y = yBase; with bottomThickness
// > 0 its inside has a floor at yBase + bottomThickness (a drinking glass), with 0 it is open (a ring).
Solid tubeSolid(double axisX, double axisZ, double yBase, double outerRadius, double innerRadius, double height,
                double bottomThickness);

// Bounding sphere of a solid (centre, radius).
void boundingSphere(const Solid& s, Vec3& centre, double& radius);

}  // namespace caustics::optics_reference
