#pragma once
// Debug-marker payloads for ID3D12GraphicsCommandList::BeginEvent / SetMarker without PIX's
// WinPixEventRuntime: metadata 0 (PIX's WINPIX_EVENT_UNICODE_VERSION) means the data is a
// null-terminated UTF-16 string, which PIX, RenderDoc and NSight show as the event name.
#include <string>
#include <string_view>

namespace caustics::rhi::d3d12 {

constexpr unsigned kMarkerMetadataUnicode = 0;

// UTF-8 -> UTF-16 with a terminating zero; invalid bytes become U+FFFD.
std::u16string markerPayload(std::string_view utf8);

}  // namespace caustics::rhi::d3d12
