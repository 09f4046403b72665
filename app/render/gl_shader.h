// Compiling and linking GLSL programs, with the driver's log on failure.
#pragma once

#include "gl_api.h"

#include <string>

// Builds a program from vertex and fragment source. Returns 0 and fills `error` on failure.
// `defines` (e.g. "#define PATTERNED\n") goes after the #version line of both shaders.
GLuint buildProgram(const char* vertexSource, const char* fragmentSource, const char* name,
                    std::string* error, const char* defines = "");
