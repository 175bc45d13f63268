#include "still_render.h"

#include <algorithm>
#include <cmath>

#include "common/tone_map.h"

namespace caustics::sample {
namespace {

// AOVs shown through the composite's tone map; the others (albedo, normal, depth) are deterministic
// visualisations, so their last frame's display image is already the mean.
bool isToneMapped(Aov aov) { return aov == Aov::Final || aov == Aov::Direct || aov == Aov::Caustics; }

uint8_t unorm8(float v) { return uint8_t(std::lround(std::clamp(v, 0.0f, 1.0f) * 255.0f)); }

// The composite pass's display transform (shaders/common/tone_map.h) applied to the mean.
void toneMap(FrameImages& images, float exposure) {
    size_t pixels = size_t(images.width) * images.height;
    images.display.resize(pixels * 4);
    for (size_t i = 0; i < pixels; ++i) {
        glm::vec3 linear(images.hdr[4 * i], images.hdr[4 * i + 1], images.hdr[4 * i + 2]);
        glm::vec3 shown = shader::srgbEncode(shader::acesFitted(linear * exposure));
        for (int c = 0; c < 3; ++c) images.display[4 * i + c] = unorm8(shown[c]);
        images.display[4 * i + 3] = 255;
    }
}

}  // namespace

Result<FrameImages> renderStill(FrameRenderer& renderer, const scene::Camera& camera, const CliOptions& o) {
    const uint32_t accumulate = o.controls.accumulate;
    const uint32_t frames = accumulate > 0 ? accumulate : o.frames;
    renderer.graph().setTimingWindow(std::max(1u, frames));
    std::vector<double> sum;
    for (uint32_t f = 0; f < frames; ++f) {
        bool last = f + 1 == frames;
        Status st = renderer.render(camera, f, accumulate > 0 || last);
        if (!st) return makeError("frame " + std::to_string(f) + ": " + st.message());
        if (accumulate == 0) continue;
        const std::vector<float>& hdr = renderer.images().hdr;
        sum.resize(hdr.size(), 0.0);
        for (size_t i = 0; i < hdr.size(); ++i) sum[i] += hdr[i];
    }
    FrameImages images = renderer.images();
    if (accumulate == 0) return images;
    for (size_t i = 0; i < sum.size(); ++i) images.hdr[i] = float(sum[i] / double(accumulate));
    if (isToneMapped(o.aov)) toneMap(images, o.exposure);
    return images;
}

}  // namespace caustics::sample
