// The OpenGL 3.3 core API, with prototypes: gl* symbols bind at link time, to libOpenGL (glvnd)
// in the window executable and to libOSMesa in the offscreen one. Include this, never GL/gl.h.
#pragma once

#ifndef GL_GLEXT_PROTOTYPES
#define GL_GLEXT_PROTOTYPES 1
#endif
#include <GL/gl.h>
#include <GL/glext.h>
