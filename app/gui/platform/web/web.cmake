# The browser build's mains (scripts/web.sh), written into SANDBOX_WEB_OUT:
#   index.html, sw.js, sandbox.js, sandbox.wasm, sandbox.data   the page as a static folder any
#       web server can serve (sandbox.data: the shipped scenes and lessons and the UI font,
#       preloaded into the browser's file system; sw.js keeps it working offline once visited)
#   sandbox-offline.html   the same app in one file (the wasm and the data inside, base64), for
#       use without a server or a network: opened from disk or a USB stick
set(SANDBOX_WEB_OUT ${CMAKE_BINARY_DIR}/site CACHE PATH "Where the browser build's page goes")
set(SANDBOX_WEB_FONT /usr/share/fonts/truetype/dejavu/DejaVuSans.ttf)
if(NOT EXISTS ${SANDBOX_WEB_FONT})
  message(FATAL_ERROR "${SANDBOX_WEB_FONT} is missing (package fonts-dejavu-core)")
endif()
set(WEB_DIR ${CMAKE_CURRENT_SOURCE_DIR}/platform/web)
get_filename_component(SHIPPED_SCENES ${CMAKE_CURRENT_SOURCE_DIR}/../scenes ABSOLUTE)
get_filename_component(SHIPPED_LESSONS ${PROJECT_SOURCE_DIR}/lessons ABSOLUTE)
file(GLOB SHIPPED_SCENE_FILES CONFIGURE_DEPENDS ${SHIPPED_SCENES}/*.json ${SHIPPED_LESSONS}/*.json)

# The files with a thread_local, without bulk memory (cmake/web.cmake says why).
set_source_files_properties(ui/label_placement.cpp platform/ui_renderer/ui_draw_runs.cpp PROPERTIES
                            COMPILE_OPTIONS -mno-bulk-memory)

# The main and the canvas, compiled once for both.
add_library(sandbox_web_main OBJECT platform/main_web.cpp platform/canvas_web.cpp
                                    platform/web/control_probe.cpp ${AUDIO_DIR}/audio_out.cpp)
set_source_files_properties(platform/web/control_probe.cpp PROPERTIES
                            COMPILE_DEFINITIONS IMGUI_ENABLE_TEST_ENGINE)
target_include_directories(sandbox_web_main PRIVATE platform)
target_link_libraries(sandbox_web_main PUBLIC sandbox_frames glfw)
sandbox_warnings(sandbox_web_main)

# Where the shipped files go in the browser's file system: preloaded from sandbox.data by the
# folder build, embedded in the wasm by the one-file build.
function(sandbox_web_files target how)
  target_link_options(${target} PRIVATE
    -sALLOW_MEMORY_GROWTH=1
    -lopenal
    -sEXPORTED_RUNTIME_METHODS=ccall,FS
    "SHELL:${how} ${SHIPPED_SCENES}@/scenes"
    "SHELL:${how} ${SHIPPED_LESSONS}@/lessons"
    "SHELL:${how} ${SANDBOX_WEB_FONT}@${SANDBOX_WEB_FONT}")
  set_property(TARGET ${target} APPEND PROPERTY LINK_DEPENDS ${SHIPPED_SCENE_FILES})
endfunction()

add_executable(sandbox-web)
target_link_libraries(sandbox-web PRIVATE sandbox_web_main)
set_target_properties(sandbox-web PROPERTIES OUTPUT_NAME sandbox
                      RUNTIME_OUTPUT_DIRECTORY ${SANDBOX_WEB_OUT})
sandbox_web_files(sandbox-web --preload-file)

add_executable(sandbox-web-offline)
target_link_libraries(sandbox-web-offline PRIVATE sandbox_web_main)
set_target_properties(sandbox-web-offline PROPERTIES OUTPUT_NAME sandbox-offline
                      RUNTIME_OUTPUT_DIRECTORY ${CMAKE_CURRENT_BINARY_DIR}/offline)
sandbox_web_files(sandbox-web-offline --embed-file)
target_link_options(sandbox-web-offline PRIVATE -sSINGLE_FILE=1)

foreach(file index.html sw.js)
  add_custom_command(OUTPUT ${SANDBOX_WEB_OUT}/${file}
    COMMAND ${CMAKE_COMMAND} -E copy ${WEB_DIR}/${file} ${SANDBOX_WEB_OUT}/${file}
    DEPENDS ${WEB_DIR}/${file})
endforeach()
add_custom_command(OUTPUT ${SANDBOX_WEB_OUT}/sandbox-offline.html
  COMMAND ${CMAKE_COMMAND} -DPAGE=${WEB_DIR}/index.html
          -DSCRIPT=$<TARGET_FILE:sandbox-web-offline> -DOUT=${SANDBOX_WEB_OUT}/sandbox-offline.html
          -P ${WEB_DIR}/one_file.cmake
  DEPENDS sandbox-web-offline ${WEB_DIR}/index.html ${WEB_DIR}/one_file.cmake)
add_custom_target(sandbox-web-page ALL DEPENDS ${SANDBOX_WEB_OUT}/index.html
  ${SANDBOX_WEB_OUT}/sw.js ${SANDBOX_WEB_OUT}/sandbox-offline.html)
