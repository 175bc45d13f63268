#pragma once
// Imports a host G-buffer (caustics/gbuffer.h contract) into the graph, refusing a texture the passes
// cannot use with a message that names the channel and the problem (format, size, usage). With an
// objectIdMap the host's ids are mapped to the module's by `remap` (the returned objectId is ours).
#include "../gbuffer/object_id_remap_pass.h"
#include "caustics/caustics_settings.h"
#include "caustics/gbuffer.h"
#include "caustics/render_graph/render_graph.h"

namespace caustics {

Result<GBuffer> importHostGBuffer(rg::RenderGraph& graph, const HostGBuffer& host, uint32_t width, uint32_t height,
                                  const CausticsSettings& settings, const ObjectIdRemapPass& remap);

}  // namespace caustics
