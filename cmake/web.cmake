# The browser build's dependencies (scripts/web.sh configures with emcmake, so EMSCRIPTEN is set).
# Emscripten's sysroot cannot take /usr/include whole (glibc's headers would shadow its own), so
# the header-only Debian packages come in one by one, and the targets the desktop build finds
# with find_package / pkg-config are defined here under the same names:
#   nlohmann_json::nlohmann_json, CLI11::CLI11  headers of nlohmann-json3-dev, libcli11-dev
#   PkgConfig::STB                              libstb-dev's headers (implementations compiled in)
#   PkgConfig::IMGUI                            Dear ImGui 1.86 compiled from Debian's source
#                                               package (SANDBOX_IMGUI_SOURCE_DIR, fetched by
#                                               scripts/web.sh), with the GLFW backend
#   glfw                                        emscripten's built-in GLFW 3 (-sUSE_GLFW=3)
#   Threads::Threads                            empty: the web build runs on one thread
# Scene files are parsed by nlohmann-json, which reports errors by throwing: keep C++ exceptions,
# as WebAssembly's own (-fwasm-exceptions: try/catch inside the wasm, no cost where nothing throws).
# Emscripten's JavaScript way (-fexceptions) sent every call that might throw from a function with
# something to clean up out to JavaScript and back (its invoke_ wrappers): about a tenth of a
# frame. Debian's emscripten ships its C++ libraries built this way (libc++-except.a,
# libc++abi-except.a, libunwind-except.a in its cache): nothing to build. Browsers run it since
# Chrome 95, Firefox 100 and Safari 15.2.
add_compile_options(-fwasm-exceptions)
add_link_options(-fwasm-exceptions)
# WebAssembly's bulk memory (-mbulk-memory): a memcpy or memset of the app's code is one
# memory.copy / memory.fill instruction; without it emscripten's memcpy sends every copy of 512
# bytes or more out to JavaScript (emscripten_memcpy_big: the frame's vertex and index arrays).
# Browsers run it since Chrome 75, Firefox 79 and Safari 15. Clang 14 keeps thread_local storage
# when bulk memory is on and the linker then asks for atomics (threads): the two files with a
# thread_local (one thread here, so it is an ordinary static) are compiled without it
# (app/gui/platform/web/web.cmake); a new thread_local elsewhere fails the link and goes there too.
add_compile_options(-mbulk-memory)
add_link_options(-mbulk-memory)
# WebAssembly SIMD (-msimd128): clang's vectoriser works four floats or two doubles at a time
# (in the profile: the label placement's rectangle tests most). With bulk memory gas_500's frame
# with every overlay takes 0.73 to 0.89 of the time (five sittings of tests/bench/
# web_frame_bench.py under load; -flto added nothing more).
# The same IEEE operations on each lane, no fused multiply-add: the same numbers and pixels.
# Browsers run it since Chrome 91, Firefox 89 and Safari 16.4; -DSANDBOX_WEB_SIMD=OFF
# (scripts/web.sh build -DSANDBOX_WEB_SIMD=OFF) builds for an older Safari.
option(SANDBOX_WEB_SIMD "WebAssembly SIMD (-msimd128): Safari 16.4 or newer" ON)
if(SANDBOX_WEB_SIMD)
  add_compile_options(-msimd128)
  add_link_options(-msimd128)
endif()

set(SANDBOX_IMGUI_SOURCE_DIR "" CACHE PATH "Dear ImGui 1.86 sources (apt-get source imgui)")
if(NOT EXISTS "${SANDBOX_IMGUI_SOURCE_DIR}/imgui.cpp")
  message(FATAL_ERROR "SANDBOX_IMGUI_SOURCE_DIR must hold Dear ImGui 1.86's sources "
                      "(scripts/web.sh build fetches them)")
endif()

# /usr/include/nlohmann and /usr/include/CLI seen through a folder of their own.
set(SANDBOX_WEB_INCLUDE ${CMAKE_BINARY_DIR}/web-include)
file(MAKE_DIRECTORY ${SANDBOX_WEB_INCLUDE})
foreach(dir nlohmann CLI)
  if(NOT EXISTS /usr/include/${dir})
    message(FATAL_ERROR "/usr/include/${dir} is missing (scripts/install-deps.sh installs it)")
  endif()
  file(CREATE_LINK /usr/include/${dir} ${SANDBOX_WEB_INCLUDE}/${dir} SYMBOLIC)
endforeach()

add_library(nlohmann_json::nlohmann_json INTERFACE IMPORTED)
target_include_directories(nlohmann_json::nlohmann_json SYSTEM INTERFACE ${SANDBOX_WEB_INCLUDE})
add_library(CLI11::CLI11 INTERFACE IMPORTED)
target_include_directories(CLI11::CLI11 SYSTEM INTERFACE ${SANDBOX_WEB_INCLUDE})
add_library(PkgConfig::STB INTERFACE IMPORTED)
target_include_directories(PkgConfig::STB SYSTEM INTERFACE /usr/include/stb)
add_library(Threads::Threads INTERFACE IMPORTED)

# The WebGL context without every extension the browser offers switched on (emscripten's default
# asks for each, about 44 ms of the first frame under SwiftShader): the app uses WebGL 2's core only.
add_library(glfw INTERFACE IMPORTED)
target_link_options(glfw INTERFACE -sUSE_GLFW=3 -sMIN_WEBGL_VERSION=2 -sMAX_WEBGL_VERSION=2
                    -sGL_SUPPORT_AUTOMATIC_ENABLE_EXTENSIONS=0)

# ImGui as Debian builds it (the same stb_truetype and stb_rect_pack, so glyphs rasterise alike),
# plus the GLFW backend that Debian's libimgui.a carries.
set(IMGUI_DIR ${SANDBOX_IMGUI_SOURCE_DIR})
add_library(imgui_web STATIC
  ${IMGUI_DIR}/imgui.cpp
  ${IMGUI_DIR}/imgui_draw.cpp
  ${IMGUI_DIR}/imgui_tables.cpp
  ${IMGUI_DIR}/imgui_widgets.cpp
  ${IMGUI_DIR}/misc/cpp/imgui_stdlib.cpp
  ${IMGUI_DIR}/backends/imgui_impl_glfw.cpp)
target_include_directories(imgui_web SYSTEM PUBLIC ${IMGUI_DIR} ${IMGUI_DIR}/backends
                           ${IMGUI_DIR}/misc/cpp)
target_include_directories(imgui_web SYSTEM PRIVATE /usr/include/stb)
# IMGUI_ENABLE_TEST_ENGINE: ImGui calls the item hooks of app/gui/platform/web/control_probe.cpp,
# through which the browser tests measure every control (off until a test asks).
target_compile_definitions(imgui_web PRIVATE
  "IMGUI_STB_TRUETYPE_FILENAME=<stb_truetype.h>" "IMGUI_STB_RECT_PACK_FILENAME=<stb_rect_pack.h>"
  IMGUI_ENABLE_TEST_ENGINE)
target_link_libraries(imgui_web PUBLIC glfw PkgConfig::STB)
add_library(PkgConfig::IMGUI ALIAS imgui_web)
set(IMGUI_INCLUDEDIR ${IMGUI_DIR})
