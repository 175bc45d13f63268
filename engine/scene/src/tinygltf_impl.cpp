// The one translation unit that compiles tinygltf's implementation. stb_image / stb_image_write
// are NOT implemented here: Debian's libstb provides them (see CMakeLists.txt).
#define TINYGLTF_IMPLEMENTATION
#include "gltf_internal.h"
