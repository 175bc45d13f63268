#include "animation_render.h"

#include <cstdio>

#include "finite_output.h"
#include "image_file.h"
#include "scene_animation.h"

namespace caustics::sample {

Result<FrameImages> renderAnimation(FrameRenderer& renderer, scene::Scene& scene, const scene::Camera& camera,
                                    const CliOptions& o) {
    const uint32_t frames = o.animation.frames;
    const bool everyFrame = o.outPath.find(kFrameToken) != std::string::npos;
    SceneAnimation animation = SceneAnimation::capture(scene);
    animation.toggles = o.animation.toggles;
    const std::vector<scene::Light> restLights = scene.lights;
    renderer.graph().setTimingWindow(frames);
    for (uint32_t f = 0; f < frames; ++f) {
        animation.apply(scene, restLights);
        bool last = f + 1 == frames;
        if (Status st = renderer.render(camera, f, last || everyFrame); !st)
            return makeError("animated frame " + std::to_string(f) + ": " + st.message());
        if (everyFrame) {
            const FrameImages& img = renderer.images();
            std::string path = framePath(o.outPath, f);
            CAUSTICS_CHECK(writeFiniteRenderedImage(path, img.width, img.height, img.display, img.hdr));
        }
        if (!last) animation.advance(kFixedFrameSeconds);
    }
    GroupPose pose = animation.groupPose(animation.objectSeconds());
    std::printf("animated %u frames (%.3f s at speed %g, %zu glass objects): glass offset (%.4f, %.4f, %.4f) m, "
                "yaw %.2f deg; light orbit %.2f deg\n",
                frames, double(animation.objectSeconds()), double(animation.toggles.speed), animation.glassCount(),
                double(pose.offset.x), double(pose.offset.y), double(pose.offset.z), double(glm::degrees(pose.yawRadians)),
                double(360.0f * animation.lightSeconds() / kAnimationPeriodSeconds));
    if (everyFrame)   // the names written, not the pattern
        std::printf("wrote %s .. %s (frames 0..%u)\n", framePath(o.outPath, 0).c_str(), framePath(o.outPath, frames - 1).c_str(),
                    frames - 1);
    return renderer.images();
}

}  // namespace caustics::sample
