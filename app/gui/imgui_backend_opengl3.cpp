// Dear ImGui's OpenGL3 renderer backend, compiled here from the source Debian ships
// (libimgui-dev) with a custom loader: gl* functions bind at link time (libOpenGL for the
// window, libOSMesa offscreen). The copy inside libimgui.a loads libGL at run time and fails
// under OSMesa (NOTES-deps.md).
#define IMGUI_IMPL_OPENGL_LOADER_CUSTOM 1
#include "gl_api.h"

#if defined(__GNUC__)
#pragma GCC diagnostic push
#pragma GCC diagnostic ignored "-Wpedantic"
#pragma GCC diagnostic ignored "-Wunused-parameter"
#pragma GCC diagnostic ignored "-Wunused-function"
#endif
#include IMGUI_OPENGL3_BACKEND_SOURCE
#if defined(__GNUC__)
#pragma GCC diagnostic pop
#endif
