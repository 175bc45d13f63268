#include "caustics/rhi/log.h"
#include "caustics/rhi/log_capture.h"

#include <cstdio>
#include <mutex>

namespace caustics {
namespace {
std::mutex& logMutex() {
    static std::mutex m;
    return m;
}
LogCallback& logSink() {
    static LogCallback sink;
    return sink;
}
const char* levelName(LogLevel level) {
    switch (level) {
        case LogLevel::Debug: return "debug";
        case LogLevel::Info: return "info";
        case LogLevel::Warning: return "warning";
        case LogLevel::Error: return "error";
    }
    return "?";
}
thread_local LogErrorCapture* innermostCapture = nullptr;
}  // namespace

LogErrorCapture::LogErrorCapture() : outer_(innermostCapture) { innermostCapture = this; }
LogErrorCapture::~LogErrorCapture() { innermostCapture = outer_; }

void LogErrorCapture::noteError(const std::string& message) {
    for (LogErrorCapture* c = innermostCapture; c; c = c->outer_)
        if (c->firstError_.empty()) c->firstError_ = message;
}

void setLogCallback(LogCallback callback) {
    std::lock_guard lock(logMutex());
    logSink() = std::move(callback);
}

void log(LogLevel level, std::string_view message) {
    if (level == LogLevel::Error && innermostCapture) LogErrorCapture::noteError(std::string(message));
    LogCallback sink;
    {
        std::lock_guard lock(logMutex());
        sink = logSink();
    }
    if (sink) {
        sink(level, message);
        return;
    }
    if (level == LogLevel::Debug) return;
    std::fprintf(stderr, "[caustics %s] %.*s\n", levelName(level), int(message.size()), message.data());
}

}  // namespace caustics
