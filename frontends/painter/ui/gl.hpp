#pragma once
/// OpenGL 3.3 core entry points. Mesa's libGL exports every core function, so
/// the prototypes are used directly (no loader); GLFW must not include its own
/// GL header, hence GLFW_INCLUDE_NONE wherever glfw3.h is included.
#define GL_GLEXT_PROTOTYPES 1
#include <GL/glcorearb.h>
