# Writes a C++ header holding every shader as a string constant, so the program runs from any
# directory. Run at build time: cmake -DOUTPUT=file.h -DSHADER_DIR=shaders [-DGLSL_ES=ON] -P this.
# The shaders are written once, in GLSL 3.30 core. With GLSL_ES (the browser build, WebGL 2) each
# is turned into GLSL ES 3.00: the #version line becomes "#version 300 es" followed by default
# precisions (highp: the shaders compute positions and pixel offsets); the rest of the language
# they use (in/out, flat, layout locations, gl_PointSize, gl_PointCoord, texture()) is the same.
file(GLOB SHADERS "${SHADER_DIR}/*.vert" "${SHADER_DIR}/*.frag")
list(SORT SHADERS)
set(content "// Generated from shaders/ by app/render/embed_shaders.cmake. Do not edit.\n#pragma once\n\nnamespace embedded_shaders {\n")
foreach(shader IN LISTS SHADERS)
  file(READ "${shader}" text)
  if(GLSL_ES)
    string(FIND "${text}" "#version 330 core\n" at)
    if(NOT at EQUAL 0)
      message(FATAL_ERROR "${shader}: must start with \"#version 330 core\" (GLSL ES is made from it)")
    endif()
    string(REPLACE "#version 330 core\n"
           "#version 300 es\nprecision highp float;\nprecision highp int;\n" text "${text}")
  endif()
  get_filename_component(name "${shader}" NAME)
  string(MAKE_C_IDENTIFIER "${name}" ident)
  string(APPEND content "inline constexpr const char* ${ident} = R\"glsl(${text})glsl\";\n")
endforeach()
string(APPEND content "}  // namespace embedded_shaders\n")
file(WRITE "${OUTPUT}.tmp" "${content}")
execute_process(COMMAND "${CMAKE_COMMAND}" -E copy_if_different "${OUTPUT}.tmp" "${OUTPUT}")
file(REMOVE "${OUTPUT}.tmp")
