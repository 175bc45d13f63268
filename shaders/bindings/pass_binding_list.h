#pragma once
// Every pass whose shader resources are declared once (shader_binding.h), and the scene's set that
// they share: the generator writes the GLSL and HLSL declarations of each. A pass adopting the scheme adds its declaration here and its
// name to CAUSTICS_PASS_BINDINGS (shaders/bindings/CMakeLists.txt).
#include "caustics_output/caustics_output_bindings.h"
#include "composite/composite_bindings.h"
#include "caustic_maps/caustic_map_bindings.h"
#include "caustic_maps/emitters_bindings.h"
#include "caustic_maps/grid_from_count_bindings.h"
#include "caustic_maps/photon_plan_bindings.h"
#include "caustic_filter/atrous_bindings.h"
#include "caustic_filter/output_bindings.h"
#include "caustic_filter/resolve_bindings.h"
#include "caustic_filter/temporal_bindings.h"
#include "caustic_filter/tiles_bindings.h"
#include "caustic_filter/variance_bindings.h"
#include "direct_lighting/direct_lighting_bindings.h"
#include "forward_trace/forward_bindings.h"
#include "gbuffer/gbuffer_bindings.h"
#include "gbuffer/remap_object_ids_bindings.h"
#include "backward_trace/backward_bindings.h"
#include "backward_trace/gather_bindings.h"
#include "backward_trace/second_type_guides_bindings.h"
#include "backward_trace/specular_pixels_bindings.h"
#include "backward_trace/second_type_guide_fill_bindings.h"
#include "caustic_filter/combine_types_bindings.h"
#include "module/scene_set_bindings.h"

namespace caustics::shader_bindings {

inline constexpr const PassBindings* kAllPasses[] = {&kCompositeBindings, &kRemapObjectIdsBindings, &kGridFromCountBindings, &kPhotonPlanBindings,
                                                     &kCausticAtrousPairsBindings, &kCausticAtrousBindings, &kCausticAtrousLastBindings, &kCausticVarianceBindings,
                                                     &kCausticFilterOutputBindings, &kCausticResolveBindings,
                                                     &kCausticFilterTilesBindings, &kCausticTileListBindings, &kCausticTemporalBindings,
                                                     &kForwardBindings, &kForwardFixedBindings, &kForwardFixed64Bindings,
                                                     &kEmittersBindings, &kCausticMapBindings,
                                                     &kDirectLightingBindings, &kGBufferBindings,
                                                     &kSecondTypeGuidesBindings, &kSecondTypeGuideFillBindings,
                                                     &kCombineTypesBindings, &kCausticsOutputBindings,
                                                     &kBackwardBindings, &kGatherBindings, &kGatherFixedBindings,
                                                     &kGatherFixed64Bindings, &kSpecularPixelsBindings,
                                                     &kSceneSetBindings};

}  // namespace caustics::shader_bindings
