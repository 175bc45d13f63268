#include "counting_proc_addr.h"

#include <cstring>

namespace caustics::test {
namespace {

ProcAddrLog gLog;
PFN_vkGetDeviceProcAddr gRealGetDeviceProcAddr = nullptr;
PFN_vkCreateBuffer gRealCreateBuffer = nullptr;
PFN_vkCmdDispatch gRealCmdDispatch = nullptr;
PFN_vkQueueSubmit2 gRealQueueSubmit2 = nullptr;
PFN_vkQueueSubmit gRealQueueSubmit = nullptr;
PFN_vkCmdUpdateBuffer gRealCmdUpdateBuffer = nullptr;
PFN_vkCmdCopyBuffer gRealCmdCopyBuffer = nullptr;

VKAPI_ATTR void VKAPI_CALL countingCmdUpdateBuffer(VkCommandBuffer cmd, VkBuffer buffer, VkDeviceSize offset,
                                                   VkDeviceSize bytes, const void* data) {
    gLog.bufferUploadBytes += bytes;
    gRealCmdUpdateBuffer(cmd, buffer, offset, bytes, data);
}

VKAPI_ATTR void VKAPI_CALL countingCmdCopyBuffer(VkCommandBuffer cmd, VkBuffer src, VkBuffer dst, uint32_t count,
                                                 const VkBufferCopy* regions) {
    for (uint32_t i = 0; i < count; ++i) gLog.bufferUploadBytes += regions[i].size;
    gRealCmdCopyBuffer(cmd, src, dst, count, regions);
}

VKAPI_ATTR VkResult VKAPI_CALL countingCreateBuffer(VkDevice device, const VkBufferCreateInfo* info,
                                                    const VkAllocationCallbacks* allocator, VkBuffer* buffer) {
    ++gLog.createBufferCalls;
    return gRealCreateBuffer(device, info, allocator, buffer);
}

VKAPI_ATTR void VKAPI_CALL countingCmdDispatch(VkCommandBuffer cmd, uint32_t x, uint32_t y, uint32_t z) {
    ++gLog.dispatchCalls;
    gRealCmdDispatch(cmd, x, y, z);
}

VKAPI_ATTR VkResult VKAPI_CALL countingQueueSubmit2(VkQueue queue, uint32_t count, const VkSubmitInfo2* submits,
                                                    VkFence fence) {
    ++gLog.queueSubmitCalls;
    return gRealQueueSubmit2(queue, count, submits, fence);
}

VKAPI_ATTR VkResult VKAPI_CALL countingQueueSubmit(VkQueue queue, uint32_t count, const VkSubmitInfo* submits,
                                                   VkFence fence) {
    ++gLog.queueSubmitCalls;
    return gRealQueueSubmit(queue, count, submits, fence);
}

// Hands out `wrapper` for `name` when it is `wanted`, keeping the driver's function in `saved`.
template <typename Fn>
bool intercept(const char* name, const char* wanted, PFN_vkVoidFunction real, Fn& saved, Fn wrapper,
               PFN_vkVoidFunction& out) {
    if (!real || std::strcmp(name, wanted) != 0) return false;
    saved = reinterpret_cast<Fn>(real);
    out = reinterpret_cast<PFN_vkVoidFunction>(wrapper);
    return true;
}

VKAPI_ATTR PFN_vkVoidFunction VKAPI_CALL recordingGetDeviceProcAddr(VkDevice device, const char* name) {
    gLog.deviceNames.insert(name);
    const PFN_vkVoidFunction real = gRealGetDeviceProcAddr(device, name);
    PFN_vkVoidFunction out = real;
    intercept(name, "vkCreateBuffer", real, gRealCreateBuffer, countingCreateBuffer, out) ||
        intercept(name, "vkCmdDispatch", real, gRealCmdDispatch, countingCmdDispatch, out) ||
        intercept(name, "vkQueueSubmit2", real, gRealQueueSubmit2, countingQueueSubmit2, out) ||
        intercept(name, "vkQueueSubmit", real, gRealQueueSubmit, countingQueueSubmit, out) ||
        intercept(name, "vkCmdUpdateBuffer", real, gRealCmdUpdateBuffer, countingCmdUpdateBuffer, out) ||
        intercept(name, "vkCmdCopyBuffer", real, gRealCmdCopyBuffer, countingCmdCopyBuffer, out);
    return out;
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
