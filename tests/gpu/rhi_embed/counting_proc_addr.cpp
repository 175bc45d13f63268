#include "counting_proc_addr.h"

#include <cstring>

namespace caustics::test {
namespace {

ProcAddrLog gLog;
PFN_vkGetDeviceProcAddr gRealGetDeviceProcAddr = nullptr;
PFN_vkCreateBuffer gRealCreateBuffer = nullptr;
PFN_vkCmdDispatch gRealCmdDispatch = nullptr;

VKAPI_ATTR VkResult VKAPI_CALL countingCreateBuffer(VkDevice device, const VkBufferCreateInfo* info,
                                                    const VkAllocationCallbacks* allocator, VkBuffer* buffer) {
    ++gLog.createBufferCalls;
    return gRealCreateBuffer(device, info, allocator, buffer);
}

VKAPI_ATTR void VKAPI_CALL countingCmdDispatch(VkCommandBuffer cmd, uint32_t x, uint32_t y, uint32_t z) {
    ++gLog.dispatchCalls;
    gRealCmdDispatch(cmd, x, y, z);
}

VKAPI_ATTR PFN_vkVoidFunction VKAPI_CALL recordingGetDeviceProcAddr(VkDevice device, const char* name) {
    gLog.deviceNames.insert(name);
    const PFN_vkVoidFunction real = gRealGetDeviceProcAddr(device, name);
    if (real && std::strcmp(name, "vkCreateBuffer") == 0) {
        gRealCreateBuffer = reinterpret_cast<PFN_vkCreateBuffer>(real);
        return reinterpret_cast<PFN_vkVoidFunction>(countingCreateBuffer);
    }
    if (real && std::strcmp(name, "vkCmdDispatch") == 0) {
        gRealCmdDispatch = reinterpret_cast<PFN_vkCmdDispatch>(real);
        return reinterpret_cast<PFN_vkVoidFunction>(countingCmdDispatch);
    }
    return real;
}

VKAPI_ATTR PFN_vkVoidFunction VKAPI_CALL recordingGetInstanceProcAddr(VkInstance instance, const char* name) {
    gLog.instanceNames.insert(name);
    const PFN_vkVoidFunction real = vkGetInstanceProcAddr(instance, name);
    if (real && std::strcmp(name, "vkGetDeviceProcAddr") == 0) {
        gRealGetDeviceProcAddr = reinterpret_cast<PFN_vkGetDeviceProcAddr>(real);
        return reinterpret_cast<PFN_vkVoidFunction>(recordingGetDeviceProcAddr);
    }
    return real;
}

}  // namespace

PFN_vkGetInstanceProcAddr countingGetInstanceProcAddr() {
    gLog = {};
    return recordingGetInstanceProcAddr;
}

const ProcAddrLog& procAddrLog() { return gLog; }

}  // namespace caustics::test
