#pragma once
// Procedural meshes for the built-in scenes: every shape is closed where a refractive object needs
// a closed surface, with outward normals and counter-clockwise front faces (glTF convention).
#include <cstdint>

#include <glm/glm.hpp>

#include "caustics/scene/scene.h"

namespace caustics::scene {

// Appends `src` transformed by `transform` to `dst` (normals by the normal matrix).
void appendMesh(Mesh& dst, const Mesh& src, const glm::mat4& transform = glm::mat4(1.0f));

// Axis-aligned box centred at the origin, flat-shaded, UVs per face scaled by `uvScale` per metre.
Mesh makeBox(const glm::vec3& halfExtent, float uvScale = 1.0f);
// Plane y = 0, x,z in [-halfX, halfX] x [-halfZ, halfZ], normal +Y, subdivided `div` x `div`.
Mesh makePlane(float halfX, float halfZ, uint32_t div = 1, float uvScale = 1.0f);
// UV sphere centred at the origin, smooth normals.
Mesh makeSphere(float radius, uint32_t segments, uint32_t rings);
// Solid cylinder along +Y from y = 0 to y = height, with caps; `rings` rows along the side.
Mesh makeCylinder(float radius, float height, uint32_t segments, uint32_t rings = 1, bool caps = true);
// Closed thick-walled tube (ring / glass wall): outer and inner walls joined by annular rims at
// y = 0 and y = height. With bottomThickness > 0 the inside has a floor at that height and the
// bottom is a solid disc (a drinking glass); with 0 it is open through (a ring).
Mesh makeTube(float outerRadius, float innerRadius, float height, uint32_t segments, float bottomThickness = 0.0f);
// Torus around +Y (major radius R, minor r).
Mesh makeTorus(float majorRadius, float minorRadius, uint32_t segments, uint32_t sides);
// Semicircular arch (extruded along Z by `depth`) spanning x in [-span/2, span/2], springing at y = 0:
// the intrados half-ring of radius span/2 and a rectangular spandrel up to `topHeight`.
Mesh makeArch(float span, float topHeight, float depth, uint32_t segments);

}  // namespace caustics::scene
