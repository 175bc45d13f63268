#pragma once
// Logging goes through a callback the host engine can replace (default: stderr).
#include <functional>
#include <string_view>

namespace caustics {

enum class LogLevel { Debug, Info, Warning, Error };

using LogCallback = std::function<void(LogLevel, std::string_view)>;

// Replaces the process-wide log sink; pass nullptr to restore the default stderr sink.
void setLogCallback(LogCallback callback);
void log(LogLevel level, std::string_view message);

}  // namespace caustics
