#include "viewer_input.h"

#include <algorithm>
#include <cctype>
#include <map>

#include <GLFW/glfw3.h>

namespace caustics::sample {

void InputQueue::attach(GLFWwindow* window) {
    glfwSetWindowUserPointer(window, this);
    glfwSetKeyCallback(window, [](GLFWwindow* w, int key, int, int action, int) {
        static_cast<InputQueue*>(glfwGetWindowUserPointer(w))->onKey(key, action);
    });
    glfwSetScrollCallback(window, [](GLFWwindow* w, double, double dy) {
        static_cast<InputQueue*>(glfwGetWindowUserPointer(w))->onScroll(float(dy));
    });
    glfwSetFramebufferSizeCallback(window, [](GLFWwindow* w, int width, int height) {
        static_cast<InputQueue*>(glfwGetWindowUserPointer(w))->onResize(width, height);
    });
}

void InputQueue::onKey(int key, int action) {
    if (action == GLFW_PRESS) {
        down_.insert(key);
        events_.push_back({InputEvent::Kind::KeyPress, key});
    } else if (action == GLFW_RELEASE) {
        down_.erase(key);
        events_.push_back({InputEvent::Kind::KeyRelease, key});
    }
}

void InputQueue::onScroll(float steps) { events_.push_back({InputEvent::Kind::Scroll, 0, steps}); }

void InputQueue::onResize(int width, int height) {
    events_.push_back({InputEvent::Kind::Resize, 0, 0.0f, width, height});
}

std::deque<InputEvent> InputQueue::take() {
    std::deque<InputEvent> out;
    out.swap(events_);
    return out;
}

int keyFromName(const std::string& name) {
    std::string n = name;
    std::transform(n.begin(), n.end(), n.begin(), [](unsigned char c) { return char(std::tolower(c)); });
    static const std::map<std::string, int> named = {
        {"escape", GLFW_KEY_ESCAPE}, {"tab", GLFW_KEY_TAB},     {"space", GLFW_KEY_SPACE},
        {"f1", GLFW_KEY_F1},         {"f12", GLFW_KEY_F12},     {"left_shift", GLFW_KEY_LEFT_SHIFT},
        {"enter", GLFW_KEY_ENTER},   {"home", GLFW_KEY_HOME},
    };
    if (auto it = named.find(n); it != named.end()) return it->second;
    if (n.size() == 1 && n[0] >= 'a' && n[0] <= 'z') return GLFW_KEY_A + (n[0] - 'a');
    if (n.size() == 1 && n[0] >= '0' && n[0] <= '9') return GLFW_KEY_0 + (n[0] - '0');
    return -1;
}

}  // namespace caustics::sample
