#pragma once
// Input of the viewer through GLFW callbacks, queued: a key tapped between two frames (press and
// release inside one slow lavapipe frame) is still seen, which per-frame polling of glfwGetKey missed.
// Scripts inject the same events (viewer_script.h), so a scripted tap takes the user's path.
#include <deque>
#include <set>
#include <string>

struct GLFWwindow;

namespace caustics::sample {

struct InputEvent {
    enum class Kind { KeyPress, KeyRelease, Scroll, Resize } kind;
    int key = 0;             // GLFW_KEY_*
    float amount = 0.0f;     // scroll steps
    int width = 0, height = 0;
};

class InputQueue {
public:
    // Installs the callbacks (before ImGui's, which chain to them) and remembers this queue.
    void attach(GLFWwindow* window);

    void onKey(int key, int action);
    void onScroll(float steps);
    void onResize(int width, int height);

    // Events since the last call, oldest first.
    std::deque<InputEvent> take();
    bool isDown(int key) const { return down_.count(key) != 0; }

private:
    std::deque<InputEvent> events_;
    std::set<int> down_;
};

// "escape", "f12", "w", "tab", ... -> GLFW_KEY_*; -1 if unknown.
int keyFromName(const std::string& name);

}  // namespace caustics::sample
