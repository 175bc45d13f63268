// The DXC interfaces of rhi/d3d12/dxc_interface.h call the vtable slots of the official dxcapi.h
// (DirectXShaderCompiler include/dxc/dxcapi.h). Each call goes through our declaration to a fake
// object whose vtable entry N records N, so a method declared out of order, or a missing base slot,
// shows up as the wrong slot number.
#include <array>
#include <cstddef>
#include <cstdint>
#include <utility>

#include <gtest/gtest.h>

#include "dxc_interface.h"

namespace caustics::rhi::d3d12::dxc {
namespace {

// dxcapi.h's order. IUnknown: QueryInterface, AddRef, Release (+ the virtual destructor's two slots on
// non-Windows, WinAdapter.h). Then, per interface, its own methods in declaration order.
constexpr int kQueryInterface = 0, kAddRef = 1, kRelease = 2;
constexpr int kBlobGetBufferPointer = kUnknownSlots + 0, kBlobGetBufferSize = kUnknownSlots + 1;
constexpr int kOperationResultGetStatus = kUnknownSlots + 0, kOperationResultGetResult = kUnknownSlots + 1,
              kOperationResultGetErrorBuffer = kUnknownSlots + 2;
constexpr int kCompiler3Compile = kUnknownSlots + 0;   // then Disassemble

int lastSlot = -1;
template <int N>
uintptr_t recordSlot(void*, uintptr_t, uintptr_t, uintptr_t, uintptr_t, uintptr_t, uintptr_t) {
    lastSlot = N;
    return 0;
}
template <int... N>
std::array<void*, sizeof...(N)> makeVtable(std::integer_sequence<int, N...>) {
    return {reinterpret_cast<void*>(&recordSlot<N>)...};
}
const auto kVtable = makeVtable(std::make_integer_sequence<int, 16>{});

// An object whose first word points at kVtable, seen through interface T.
template <typename T>
T* fake() {
    static const void* object = kVtable.data();
    return reinterpret_cast<T*>(&object);
}

template <typename Call>
int slotOf(Call call) {
    lastSlot = -1;
    call();
    return lastSlot;
}

TEST(DxcInterface, UnknownMethodsUseTheComSlots) {
    auto* u = fake<DxcUnknown>();
    EXPECT_EQ(slotOf([&] { u->QueryInterface(kIidResult, nullptr); }), kQueryInterface);
    EXPECT_EQ(slotOf([&] { u->AddRef(); }), kAddRef);
    EXPECT_EQ(slotOf([&] { u->Release(); }), kRelease);
}

TEST(DxcInterface, BlobMethodsFollowDxcapiOrder) {
    auto* b = fake<IDxcBlob>();
    EXPECT_EQ(slotOf([&] { b->GetBufferPointer(); }), kBlobGetBufferPointer);
    EXPECT_EQ(slotOf([&] { b->GetBufferSize(); }), kBlobGetBufferSize);
}

TEST(DxcInterface, OperationResultMethodsFollowDxcapiOrder) {
    auto* r = fake<IDxcOperationResult>();
    EXPECT_EQ(slotOf([&] { r->GetStatus(nullptr); }), kOperationResultGetStatus);
    EXPECT_EQ(slotOf([&] { r->GetResult(nullptr); }), kOperationResultGetResult);
    EXPECT_EQ(slotOf([&] { r->GetErrorBuffer(nullptr); }), kOperationResultGetErrorBuffer);
}

TEST(DxcInterface, Compiler3CompileIsTheFirstMethodAfterIUnknown) {
    auto* c = fake<IDxcCompiler3>();
    EXPECT_EQ(slotOf([&] { c->Compile(nullptr, nullptr, 0, nullptr, kIidResult, nullptr); }), kCompiler3Compile);
}

TEST(DxcInterface, BufferMatchesDxcapiLayout) {
    // typedef struct DxcBuffer { LPCVOID Ptr; SIZE_T Size; UINT Encoding; } DxcBuffer;
    EXPECT_EQ(offsetof(DxcBuffer, ptr), 0u);
    EXPECT_EQ(offsetof(DxcBuffer, size), sizeof(void*));
    EXPECT_EQ(offsetof(DxcBuffer, encoding), 2 * sizeof(void*));
    EXPECT_EQ(sizeof(DxcBuffer), 3 * sizeof(void*));
}

TEST(DxcInterface, GuidsAreDxcapisValues) {
    // CLSID_DxcCompiler 73e22d93-e6ce-47f3-b5bf-f0664f39c1b0, IID_IDxcCompiler3 228b4687-...,
    // IID_IDxcResult 58346cda-...: the first words identify them.
    EXPECT_EQ(kClsidDxcCompiler.Data1, 0x73e22d93u);
    EXPECT_EQ(kIidCompiler3.Data1, 0x228b4687u);
    EXPECT_EQ(kIidResult.Data1, 0x58346cdau);
    EXPECT_EQ(kIidResult.Data4[7], 0x59);
}

}  // namespace
}  // namespace caustics::rhi::d3d12::dxc
