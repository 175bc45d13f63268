#include "bench_gpu.h"

#include <algorithm>
#include <cstdio>
#include <cstring>

namespace caustics::bench {

using namespace caustics::rhi;

Result<DeviceHandle> createBenchDevice(const BenchOptions& options) {
    DeviceDesc desc;
    desc.backend = options.backend;
    desc.enableValidation = options.validation;
    desc.requireRayTracing = true;
    // Keep the table readable: the loader's and layers' info lines are dropped, problems are shown.
    desc.validationCallback = [](LogLevel level, std::string_view message) {
        if (level >= LogLevel::Warning) std::fprintf(stderr, "validation: %.*s\n", int(message.size()), message.data());
    };
    return createDevice(desc);
}

ShaderLibraryDesc benchShaderLibrary(std::string_view path, std::string exportName, ShaderStage stage) {
    std::span<const uint32_t> words = bench_shaders::spirv(path);
    ShaderLibraryDesc lib;
    lib.code.kind = ShaderCodeKind::SPIRV;
    lib.code.bytes.resize(words.size_bytes());
    if (!words.empty()) std::memcpy(lib.code.bytes.data(), words.data(), words.size_bytes());
    lib.code.debugName = std::string(path);
    lib.exports.push_back({std::move(exportName), "main", stage});
    return lib;
}

Status runOnce(IDevice& device, const std::function<void(ICommandList&)>& record) {
    CAUSTICS_TRY(CommandListHandle cmd, device.createCommandList());
    cmd->begin();
    record(*cmd);
    cmd->end();
    CAUSTICS_TRY(uint64_t fence, device.submit(cmd));
    return device.waitForFence(fence);
}

Result<std::vector<double>> timeFrames(IDevice& device, uint32_t warmupFrames, uint32_t frames,
                                       const std::function<void(ICommandList&, uint32_t)>& record) {
    CAUSTICS_TRY(TimestampPoolHandle pool, device.createTimestampPool(2));
    std::vector<double> ms;
    for (uint32_t frame = 0; frame < warmupFrames + frames; ++frame) {
        CAUSTICS_CHECK(runOnce(device, [&](ICommandList& cmd) {
            cmd.resetTimestamps(pool, 0, 2);
            cmd.writeTimestamp(pool, 0);
            record(cmd, frame);
            cmd.writeTimestamp(pool, 1);
        }));
        if (frame < warmupFrames) continue;
        auto stamps = device.readTimestamps(pool, 0, 2);
        if (stamps.size() != 2 || !stamps[0] || !stamps[1])
            return makeError("timestamps of frame " + std::to_string(frame) + " are not available");
        ms.push_back((*stamps[1] - *stamps[0]) * 1e-6);
    }
    return ms;
}

double median(std::vector<double> values) {
    if (values.empty()) return 0;
    std::sort(values.begin(), values.end());
    const size_t mid = values.size() / 2;
    return values.size() % 2 ? values[mid] : 0.5 * (values[mid - 1] + values[mid]);
}

}  // namespace caustics::bench
