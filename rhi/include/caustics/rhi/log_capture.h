#pragma once
// Errors that are only logged, caught where they must become a Status (caustics/rhi/log.h).
#include <string>

namespace caustics {

// While one lives, the first LogLevel::Error logged on this thread is also kept here (it still goes to
// the sink). The render graph wraps each pass's recording in one, so that an error a pass or the RHI
// only logs (a binding set that failed, a recording error) makes RenderGraph::execute() fail with it.
// Nested captures each see the errors logged while they live.
class LogErrorCapture {
public:
    LogErrorCapture();
    ~LogErrorCapture();
    LogErrorCapture(const LogErrorCapture&) = delete;
    LogErrorCapture& operator=(const LogErrorCapture&) = delete;
    bool failed() const { return !firstError_.empty(); }
    const std::string& firstError() const { return firstError_; }

    // Called by log() for every Error.
    static void noteError(const std::string& message);

private:
    LogErrorCapture* outer_ = nullptr;
    std::string firstError_;
};

}  // namespace caustics
