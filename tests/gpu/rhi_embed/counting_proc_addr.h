#pragma once
// A host's vkGetInstanceProcAddr that forwards to the loader's and records what it resolves, the way
// an engine on volk, its own layer dispatch or a capture interposer hands its entry points to the
// module (docs/embedding.md, "Device and resources"). vkGetDeviceProcAddr resolves to a recording
// twin too, and vkCreateBuffer, vkCmdDispatch, vkQueueSubmit(2), vkCmdUpdateBuffer and vkCmdCopyBuffer
// to counting wrappers: a call that
// reached the driver without them went around the host's pointers. The host's own calls go to the
// loader directly, so the submit count is the module's alone.
#include <vulkan/vulkan.h>

#include <set>
#include <string>

namespace caustics::test {

struct ProcAddrLog {
    std::set<std::string> instanceNames, deviceNames;   // every name resolved, by level
    int createBufferCalls = 0, dispatchCalls = 0;
    int queueSubmitCalls = 0;   // vkQueueSubmit2 and vkQueueSubmit, on any queue
    // Bytes written into buffers by recorded commands: vkCmdUpdateBuffer's dataSize and vkCmdCopyBuffer's
    // region sizes (the module's uploads; texture uploads are vkCmdCopyBufferToImage, not counted).
    uint64_t bufferUploadBytes = 0;
};

// Clears the log and returns the recording vkGetInstanceProcAddr (one at a time per process).
PFN_vkGetInstanceProcAddr countingGetInstanceProcAddr();
const ProcAddrLog& procAddrLog();

}  // namespace caustics::test
