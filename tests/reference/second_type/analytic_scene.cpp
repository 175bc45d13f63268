// Solid constructors and bounding spheres; see analytic_scene.h.
#include "analytic_scene.h"

#include <algorithm>
#include <cmath>

namespace caustics::optics_reference {

Solid sphereSolid(Vec3 centre, double radius) {
    Solid s;
    s.kind = Solid::Kind::Sphere;
    s.centre = centre;
    s.radius = radius;
    return s;
}

Solid boxSolid(Vec3 centre, Vec3 halfExtent, const glm::dmat3& axes) {
    Solid s;
    s.kind = Solid::Kind::Box;
    s.centre = centre;
    s.halfExtent = halfExtent;
    s.axes = axes;
    return s;
}

Solid paneSolid(Vec3 centre, double halfX, double halfZ, const glm::dmat3& axes) {
    return boxSolid(centre, Vec3(halfX, 0.0, halfZ), axes);
}

Solid cylinderSolid(double axisX, double axisZ, double yBase, double radius, double height) {
    Solid s;
    s.kind = Solid::Kind::Patches;
    s.centre = Vec3(axisX, yBase, axisZ);
    s.patches.push_back({Patch::Kind::Side, radius, 0.0, yBase, yBase + height, true});
    s.patches.push_back({Patch::Kind::Disk, radius, 0.0, yBase + height, 0.0, true});
    s.patches.push_back({Patch::Kind::Disk, radius, 0.0, yBase, 0.0, false});
    return s;
}

Solid tubeSolid(double axisX, double axisZ, double yBase, double outerRadius, double innerRadius, double height,
                double bottomThickness) {
    Solid s;
    s.kind = Solid::Kind::Patches;
    s.centre = Vec3(axisX, yBase, axisZ);
    double top = yBase + height, inner = yBase + bottomThickness;
    s.patches.push_back({Patch::Kind::Side, outerRadius, 0.0, yBase, top, true});
    s.patches.push_back({Patch::Kind::Side, innerRadius, 0.0, inner, top, false});
    s.patches.push_back({Patch::Kind::Disk, outerRadius, innerRadius, top, 0.0, true});
    if (bottomThickness > 0.0) {
        s.patches.push_back({Patch::Kind::Disk, outerRadius, 0.0, yBase, 0.0, false});
        s.patches.push_back({Patch::Kind::Disk, innerRadius, 0.0, inner, 0.0, true});
    } else {
        s.patches.push_back({Patch::Kind::Disk, outerRadius, innerRadius, yBase, 0.0, false});
    }
    return s;
}

void boundingSphere(const Solid& s, Vec3& centre, double& radius) {
    switch (s.kind) {
        case Solid::Kind::Sphere:
            centre = s.centre;
            radius = s.radius;
            return;
        case Solid::Kind::Box:
            centre = s.centre;
            radius = glm::length(s.halfExtent);
            return;
        case Solid::Kind::Patches: {
            double yLo = 1e300, yHi = -1e300, r = 0.0;
            for (const Patch& p : s.patches) {
                yLo = std::min(yLo, p.yMin);
                yHi = std::max({yHi, p.kind == Patch::Kind::Side ? p.yMax : p.yMin});
                r = std::max(r, p.radius);
            }
            centre = Vec3(s.centre.x, 0.5 * (yLo + yHi), s.centre.z);
            radius = std::hypot(r, 0.5 * (yHi - yLo));
            return;
        }
    }
}

}  // namespace caustics::optics_reference
