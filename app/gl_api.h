// The one place that includes OpenGL. Core entry points come straight from
// glvnd's libGL (which exports every core function) with GL_GLEXT_PROTOTYPES,
// defined by app/CMakeLists.txt; the context is 3.3 core, so only 3.3 calls are used.
#pragma once
#ifndef GL_GLEXT_PROTOTYPES
#define GL_GLEXT_PROTOTYPES 1
#endif
#include <GL/gl.h>
#include <GL/glext.h>
