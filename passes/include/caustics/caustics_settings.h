#pragma once
// Settings of the caustics module: a plain struct with documented defaults (the paper's section 4
// defaults: 512x512 maps, 1 ray per texel, depth 4). validate() refuses absurd values with a message
// naming the field and the accepted range; nothing is silently clamped.
#include <cstdint>
#include <string>

#include "caustics/rhi/result.h"

namespace caustics {

// How big the integration sphere of a backward (second-type) hit is.
enum class SphereRadiusPolicy : uint8_t {
    // radius = scale * sqrt(area of the pixel's footprint on the receiver), the footprint propagated
    // through the specular chain with ray differentials (Igehy 1999), so a lens's magnification counts;
    // the footprint width is clamped to [min, max]Magnification x the unfolded width (path length x
    // pixel angle), the radius to [sphereMinRadius, sphereMaxRadius]. docs/caustics.md. Default.
    PixelFootprint,
    // radius = worldRadius metres everywhere.
    FixedWorld,
};

enum class CausticsAov : uint8_t {
    Final,        // tone-mapped composite
    Direct,       // direct lighting with ray-traced shadows (linear)
    Caustics,     // caustic radiance of both types (linear), filtered if the filter is on
    FirstType,    // first-type caustic radiance only (linear, unfiltered)
    SecondType,   // second-type caustic radiance only (linear, unfiltered)
    Albedo, Normal, Depth,
};

struct CausticsSettings {
    uint32_t mapResolution = 512;       // caustic visibility map side, texels
    float raysPerTexel = 1.0f;          // fractional: a stochastic subset of texels emits
    // Photon budget (docs/caustics.md, "Photon budget"). 0: the paper's emission, raysPerTexel photons
    // at every emitting texel of every layer whose caustic the camera can see. > 0: this many photons
    // per frame in all, split over those layers by how much of the image their receivers cover, so the
    // cost follows the caustics in view, not the level. Unbiased either way (each photon carries its
    // texel's flux over the texel's expected photon count).
    uint32_t photonsPerFrame = 0;
    // > 0: the module steers photonsPerFrame (its start value; 2^18 when 0) so that the caustic passes
    // take this many GPU milliseconds, from the graph's timestamps of earlier frames (photon_budget.h).
    float causticTimeTargetMs = 0.0f;
    // A cluster's caustic is assumed to land within this many cluster radii of its bounding sphere
    // (view culling and the budget's weights; caustics/caustic_importance.h). Larger: fewer caustics
    // lost off screen (a mirror's reflected patch far away), more photons spent on hidden ones.
    float causticReceiverReach = 4.0f;
    uint32_t maxSpecularDepth = 4;      // specular events per caustic path
    bool russianRoulette = true;        // after the second event, by path throughput
    bool secondType = true;             // caustics seen through specular objects
    // The caustic maps rasterise the specular instances only (false) or the occluders in the light's
    // frustum too (true, the paper's light-space G-buffer). Both are unbiased: the forward ray finds
    // the true first hit; without occluders, photons leave texels behind an occluder and end on it
    // (docs/caustics.md, "Maps without occluders").
    bool mapOccluders = false;
    SphereRadiusPolicy sphereRadiusPolicy = SphereRadiusPolicy::PixelFootprint;
    float sphereRadiusScale = 0.75f;    // PixelFootprint: radius in footprint widths (camera pixels)
    float sphereWorldRadius = 0.01f;    // FixedWorld: metres
    // PixelFootprint clamps. Magnification: footprint width / unfolded width; ray differentials blow
    // up at folds of the camera path and at grazing receivers. Radii in metres. Both policies keep
    // every disk on its side of walls (tangent-plane probes) and the radius >= sphereMinRadius.
    float sphereMinMagnification = 1.0f / 64.0f;
    float sphereMaxMagnification = 16.0f;
    float sphereMinRadius = 1.0e-4f;
    float sphereMaxRadius = 0.25f;
    uint32_t maxStoredHits = 1u << 20;  // forward diffuse hits kept for the second-type gather
    // Camera paths through glass follow each event's most probable lobe with its probability as weight
    // and start a second branch (sphere) along the others with theirs, once per pixel (docs/caustics.md
    // "Second-type lobes"): no pixel loses the caustic behind the glass to a sampled Fresnel reflection.
    // Off: one lobe picked per event (the paper), one sphere per specular pixel.
    bool secondTypeSplitLobes = true;
    // The caustic filter (docs/caustics.md "Filter"; SVGF-like, the paper measured with it off).
    bool filter = true;
    // Filter the second type apart, on the receiver seen through the glass (its own guides, history and
    // motion; docs/caustics.md "Second-type guides"). Off: it is filtered with the first type on the camera
    // G-buffer, which at those pixels holds the glass. Without an AOV that shows a type alone its buffer,
    // image and guides follow the specular pixels the camera sees (list order, "Second-type memory"):
    // the filter's share is 27.5 MiB at 1080p and 109 MiB at 4K (16.5 / 65.5 merged; MemoryBudget.*).
    // On by default since 2026-12-04, when a traced pixel whose receiver the filter cannot follow (or that
    // has none) took the glass's guides instead ("Second-type guides"): before, the built-in water glass
    // kept speckles apart that the merged filter smoothed.
    bool filterSecondTypeApart = true;
    // History length cap, frames: with a still view the temporal step is the plain mean of the last
    // frames until this many, then an exponential average with weight 1 / filterMaxHistory.
    uint32_t filterMaxHistory = 32;
    // The filter history pool's first capacity, in 8x8 tiles (docs/caustics.md "Memory"); 0: a quarter of
    // the view's tiles, at least 1024. The pool grows with the caustics' coverage, keeping its history;
    // a host that knows its views' coverage sizes it here and never sees a frame outgrow it.
    uint32_t filterPoolTiles = 0;
    // Reproject the caustic history with its caster's motion (docs/caustics.md "Moving casters"): when
    // a specular instance moved since the last frame, each photon carries where it would have landed
    // under last frame's transform, and the temporal step follows that instead of the receiver; a pixel
    // that shows a moved instance (a glass ball and the caustic seen through it) follows that instance
    // ("Moving objects"). Off: a moving glass drags a trail that only the photon-count test clears.
    bool filterCasterMotion = true;
    // Edge-aware a-trous iterations (steps 1, 2, 4, ...; 3 spans 29 pixels); 0 = temporal only. With the
    // Gaussian luminance weight a fourth and fifth iteration change the image by < 0.2 % (docs/caustics.md).
    uint32_t atrousIterations = 3;
    // Luminance edge-stopping: the weight is exp(-d^2 / 2) with d the luminance difference in units of
    // this many standard deviations of its estimated noise. Smaller keeps more detail and more noise.
    float filterLuminanceSigma = 1.0f;
    float exposure = 1.0f;
    uint32_t seed = 1;
    // Added by the module helper: which image CausticsModule's `display` output shows (FirstType and
    // SecondType fall back to Caustics where the caustic passes do not export them separately), and a
    // switch for the caustic passes as a whole (off: caustic radiance is zero, direct lighting stays).
    CausticsAov aov = CausticsAov::Final;
    bool causticsEnabled = true;
    // Embedding (docs/embedding.md). causticsOnly: the host composites; none of our G-buffer, direct
    // lighting or composite passes run, FrameInputs::hostGBuffer is required and the outputs are the
    // linear caustic radiance images. framesInFlight: how many frames the host keeps on the GPU at
    // once (frame n reuses the per-frame buffers of frame n - framesInFlight); fixed at create().
    bool causticsOnly = false;
    uint32_t framesInFlight = 3;

    // Limits beyond which a setting is refused (not clamped).
    static constexpr uint32_t kMaxMapResolution = 8192;
    static constexpr float kMaxRaysPerTexel = 256.0f;
    static constexpr uint32_t kMaxPhotonsPerFrame = 1u << 28;
    static constexpr float kMaxCausticTimeTargetMs = 1000.0f;
    static constexpr float kMaxCausticReceiverReach = 1000.0f;
    static constexpr uint32_t kMaxSpecularDepth = 31;
    static constexpr uint32_t kMaxStoredHits = 1u << 26;
    static constexpr uint32_t kMaxFramesInFlight = 16;
    static constexpr uint32_t kMaxFilterHistory = 1024;
    static constexpr uint32_t kMaxFilterPoolTiles = 1u << 21;   // a 16384^2 view
    static constexpr uint32_t kMaxAtrousIterations = 8;
    static constexpr float kMaxFilterLuminanceSigma = 1000.0f;

    Status validate() const;
};

}  // namespace caustics
