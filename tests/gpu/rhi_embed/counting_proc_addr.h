#pragma once
// A host's vkGetInstanceProcAddr that forwards to the loader's and records what it resolves, the way
// an engine on volk, its own layer dispatch or a capture interposer hands its entry points to the
// module (docs/embedding.md, "Device and resources"). vkGetDeviceProcAddr resolves to a recording
// twin too, and vkCreateBuffer and vkCmdDispatch to counting wrappers: a call that reached the driver
// without them went around the host's pointers.
#include <vulkan/vulkan.h>

#include <set>
#include <string>

namespace caustics::test {

struct ProcAddrLog {
    std::set<std::string> instanceNames, deviceNames;   // every name resolved, by level
    int createBufferCalls = 0, dispatchCalls = 0;
};

// Clears the log and returns the recording vkGetInstanceProcAddr (one at a time per process).
PFN_vkGetInstanceProcAddr countingGetInstanceProcAddr();
const ProcAddrLog& procAddrLog();

}  // namespace caustics::test
