// The OpenGL API, with prototypes: gl* symbols bind at link time, to libOpenGL (glvnd) in the
// window executable, to libOSMesa in the offscreen one, and to emscripten's WebGL 2 in the
// browser build. Include this, never GL/gl.h.
//   desktop: OpenGL 3.3 core           SANDBOX_GL_ES 0
//   browser: OpenGL ES 3.0 (WebGL 2)   SANDBOX_GL_ES 1: no wide lines, no base vertex, point
//            size always set by the vertex shader, shaders in GLSL ES 3.00 (generated at build
//            time from shaders/, see app/render/embed_shaders.cmake)
#pragma once

#ifdef __EMSCRIPTEN__
#include <GLES3/gl3.h>
#define SANDBOX_GL_ES 1
#else
#ifndef GL_GLEXT_PROTOTYPES
#define GL_GLEXT_PROTOTYPES 1
#endif
#include <GL/gl.h>
#include <GL/glext.h>
#define SANDBOX_GL_ES 0
#endif
