// The host tables the shaders read, held against their one shader-side declaration
// (shaders/common/scene.h, camera_constants.h, caustic_map.h, caustic_hit.h; docs/shaders.md, "Scene API"): the shared-dialect
// structs compile here as C++, and every member must sit at the host struct's offset. A mismatch
// fails the build, naming the member.
#include <cstddef>

#include "caustics/camera_constants.h"
#include "caustics/caustic_map_plan.h"
#include "caustics/caustic_passes.h"
#include "caustics/gpu_light.h"
#include "caustics/scene/gpu_scene.h"
#include "caustics/scene/gpu_types.h"
#include "common/camera.h"
#include "common/caustic_hit.h"
#include "common/caustic_map.h"
#include "common/scene.h"

namespace caustics {
namespace {

#define CAUSTICS_SAME_MEMBER(Host, Shader, member) \
    static_assert(offsetof(Host, member) == offsetof(Shader, member) && \
                      sizeof(Host::member) == sizeof(Shader::member), \
                  #Host "::" #member " differs from its shader declaration")

using HostMaterial = scene::GpuMaterial;
using ShaderMaterial = shader::GpuMaterial;
static_assert(sizeof(HostMaterial) == sizeof(ShaderMaterial));
CAUSTICS_SAME_MEMBER(HostMaterial, ShaderMaterial, baseColor);
CAUSTICS_SAME_MEMBER(HostMaterial, ShaderMaterial, metallic);
CAUSTICS_SAME_MEMBER(HostMaterial, ShaderMaterial, specularColor);
CAUSTICS_SAME_MEMBER(HostMaterial, ShaderMaterial, roughness);
CAUSTICS_SAME_MEMBER(HostMaterial, ShaderMaterial, attenuationColor);
CAUSTICS_SAME_MEMBER(HostMaterial, ShaderMaterial, attenuationDistance);
CAUSTICS_SAME_MEMBER(HostMaterial, ShaderMaterial, emissive);
CAUSTICS_SAME_MEMBER(HostMaterial, ShaderMaterial, ior);
CAUSTICS_SAME_MEMBER(HostMaterial, ShaderMaterial, transmission);
CAUSTICS_SAME_MEMBER(HostMaterial, ShaderMaterial, specular);
CAUSTICS_SAME_MEMBER(HostMaterial, ShaderMaterial, thickness);
CAUSTICS_SAME_MEMBER(HostMaterial, ShaderMaterial, baseColorTexture);
CAUSTICS_SAME_MEMBER(HostMaterial, ShaderMaterial, flags);
static_assert(scene::kMaterialSpecular == shader::kMaterialSpecular &&
              scene::kMaterialTransmissive == shader::kMaterialTransmissive &&
              scene::kMaterialMetallic == shader::kMaterialMetallic &&
              scene::kMaterialDoubleSided == shader::kMaterialDoubleSided &&
              scene::kMaterialThinWalled == shader::kMaterialThinWalled &&
              scene::kInstanceSpecular == shader::kInstanceSpecular &&
              scene::kMaskDiffuse == shader::kMaskDiffuse && scene::kMaskSpecular == shader::kMaskSpecular);

using HostInstance = scene::GpuInstance;
using ShaderInstance = shader::GpuInstance;
static_assert(sizeof(HostInstance) == sizeof(ShaderInstance));
CAUSTICS_SAME_MEMBER(HostInstance, ShaderInstance, objectToWorld);
CAUSTICS_SAME_MEMBER(HostInstance, ShaderInstance, normalToWorld);
CAUSTICS_SAME_MEMBER(HostInstance, ShaderInstance, material);
CAUSTICS_SAME_MEMBER(HostInstance, ShaderInstance, firstVertex);
CAUSTICS_SAME_MEMBER(HostInstance, ShaderInstance, firstIndex);
CAUSTICS_SAME_MEMBER(HostInstance, ShaderInstance, triangleCount);
CAUSTICS_SAME_MEMBER(HostInstance, ShaderInstance, objectId);
CAUSTICS_SAME_MEMBER(HostInstance, ShaderInstance, mesh);
CAUSTICS_SAME_MEMBER(HostInstance, ShaderInstance, flags);

using HostVertex = scene::GpuVertex;
using ShaderVertex = shader::GpuVertex;
static_assert(sizeof(HostVertex) == sizeof(ShaderVertex));
CAUSTICS_SAME_MEMBER(HostVertex, ShaderVertex, normal);
CAUSTICS_SAME_MEMBER(HostVertex, ShaderVertex, u);
CAUSTICS_SAME_MEMBER(HostVertex, ShaderVertex, tangent);
CAUSTICS_SAME_MEMBER(HostVertex, ShaderVertex, v);

using ShaderLight = shader::GpuLight;
static_assert(sizeof(GpuLight) == sizeof(ShaderLight));
CAUSTICS_SAME_MEMBER(GpuLight, ShaderLight, position);
CAUSTICS_SAME_MEMBER(GpuLight, ShaderLight, type);
CAUSTICS_SAME_MEMBER(GpuLight, ShaderLight, direction);
CAUSTICS_SAME_MEMBER(GpuLight, ShaderLight, range);
CAUSTICS_SAME_MEMBER(GpuLight, ShaderLight, intensity);
CAUSTICS_SAME_MEMBER(GpuLight, ShaderLight, cosInner);
CAUSTICS_SAME_MEMBER(GpuLight, ShaderLight, cosOuter);
CAUSTICS_SAME_MEMBER(GpuLight, ShaderLight, castsCaustics);
static_assert(kGpuLightPoint == shader::kLightPoint && kGpuLightSpot == shader::kLightSpot &&
              kGpuLightDirectional == shader::kLightDirectional);

using ShaderCamera = shader::CameraConstants;
static_assert(sizeof(CameraConstants) == sizeof(ShaderCamera));
CAUSTICS_SAME_MEMBER(CameraConstants, ShaderCamera, view);
CAUSTICS_SAME_MEMBER(CameraConstants, ShaderCamera, proj);
CAUSTICS_SAME_MEMBER(CameraConstants, ShaderCamera, viewProj);
CAUSTICS_SAME_MEMBER(CameraConstants, ShaderCamera, invViewProj);
CAUSTICS_SAME_MEMBER(CameraConstants, ShaderCamera, prevViewProj);
CAUSTICS_SAME_MEMBER(CameraConstants, ShaderCamera, eye);
CAUSTICS_SAME_MEMBER(CameraConstants, ShaderCamera, forward);
CAUSTICS_SAME_MEMBER(CameraConstants, ShaderCamera, right);
CAUSTICS_SAME_MEMBER(CameraConstants, ShaderCamera, up);
CAUSTICS_SAME_MEMBER(CameraConstants, ShaderCamera, clip);
CAUSTICS_SAME_MEMBER(CameraConstants, ShaderCamera, frame);

using ShaderMap = shader::CausticMap;
static_assert(sizeof(CausticMapGpu) == sizeof(ShaderMap));
CAUSTICS_SAME_MEMBER(CausticMapGpu, ShaderMap, origin);
CAUSTICS_SAME_MEMBER(CausticMapGpu, ShaderMap, light);
CAUSTICS_SAME_MEMBER(CausticMapGpu, ShaderMap, right);
CAUSTICS_SAME_MEMBER(CausticMapGpu, ShaderMap, extent);
CAUSTICS_SAME_MEMBER(CausticMapGpu, ShaderMap, up);
CAUSTICS_SAME_MEMBER(CausticMapGpu, ShaderMap, orthographic);
CAUSTICS_SAME_MEMBER(CausticMapGpu, ShaderMap, forward);
CAUSTICS_SAME_MEMBER(CausticMapGpu, ShaderMap, nearPlane);
CAUSTICS_SAME_MEMBER(CausticMapGpu, ShaderMap, intensity);
CAUSTICS_SAME_MEMBER(CausticMapGpu, ShaderMap, cosInner);
CAUSTICS_SAME_MEMBER(CausticMapGpu, ShaderMap, spotAxis);
CAUSTICS_SAME_MEMBER(CausticMapGpu, ShaderMap, cosOuter);
CAUSTICS_SAME_MEMBER(CausticMapGpu, ShaderMap, viewProj);
CAUSTICS_SAME_MEMBER(CausticMapGpu, ShaderMap, range);
CAUSTICS_SAME_MEMBER(CausticMapGpu, ShaderMap, photons);
CAUSTICS_SAME_MEMBER(CausticMapGpu, ShaderMap, cluster);
CAUSTICS_SAME_MEMBER(CausticMapGpu, ShaderMap, ownerRow);

// The stored hit: the host decodes the same record (caustic_passes.h).
using ShaderHit = shader::CausticHitRecord;
static_assert(sizeof(CausticHit) == sizeof(ShaderHit));
CAUSTICS_SAME_MEMBER(CausticHit, ShaderHit, position);
CAUSTICS_SAME_MEMBER(CausticHit, ShaderHit, objectId);
CAUSTICS_SAME_MEMBER(CausticHit, ShaderHit, flux);
CAUSTICS_SAME_MEMBER(CausticHit, ShaderHit, light);
CAUSTICS_SAME_MEMBER(CausticHit, ShaderHit, baseColor);
CAUSTICS_SAME_MEMBER(CausticHit, ShaderHit, dielectricF0);
CAUSTICS_SAME_MEMBER(CausticHit, ShaderHit, normal);
CAUSTICS_SAME_MEMBER(CausticHit, ShaderHit, incoming);
CAUSTICS_SAME_MEMBER(CausticHit, ShaderHit, metallicRoughness);
CAUSTICS_SAME_MEMBER(CausticHit, ShaderHit, transmission);
using ShaderSphere = shader::CausticSphere;
static_assert(sizeof(CausticSphere) == sizeof(ShaderSphere));
CAUSTICS_SAME_MEMBER(CausticSphere, ShaderSphere, centre);
CAUSTICS_SAME_MEMBER(CausticSphere, ShaderSphere, radius);
CAUSTICS_SAME_MEMBER(CausticSphere, ShaderSphere, transmittance);
CAUSTICS_SAME_MEMBER(CausticSphere, ShaderSphere, objectId);
CAUSTICS_SAME_MEMBER(CausticSphere, ShaderSphere, normal);
CAUSTICS_SAME_MEMBER(CausticSphere, ShaderSphere, pixel);
CAUSTICS_SAME_MEMBER(CausticSphere, ShaderSphere, outgoing);
CAUSTICS_SAME_MEMBER(CausticSphere, ShaderSphere, likelyPath);

#undef CAUSTICS_SAME_MEMBER

}  // namespace
}  // namespace caustics
