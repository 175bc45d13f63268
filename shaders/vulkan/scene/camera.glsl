#ifndef CAUSTICS_SCENE_CAMERA_GLSL
#define CAUSTICS_SCENE_CAMERA_GLSL
// The camera constants and their functions are the shared dialect's common/camera.h.
#include "common/camera.h"
#endif
