# The browser build's main (scripts/web.sh): sandbox.js, sandbox.wasm and sandbox.data (the
# shipped scenes and lessons and the UI font, preloaded into the browser's file system) written with
# index.html into SANDBOX_WEB_OUT, a static folder any web server can serve.
set(SANDBOX_WEB_OUT ${CMAKE_BINARY_DIR}/site CACHE PATH "Where the browser build's page goes")
set(SANDBOX_WEB_FONT /usr/share/fonts/truetype/dejavu/DejaVuSans.ttf)
if(NOT EXISTS ${SANDBOX_WEB_FONT})
  message(FATAL_ERROR "${SANDBOX_WEB_FONT} is missing (package fonts-dejavu-core)")
endif()
set(WEB_DIR ${CMAKE_CURRENT_SOURCE_DIR}/platform/web)

add_executable(sandbox-web platform/main_web.cpp platform/canvas_web.cpp platform/audio_out.cpp)
target_include_directories(sandbox-web PRIVATE platform)
target_link_libraries(sandbox-web PRIVATE sandbox_ui sandbox_ui_renderer glfw)
set_target_properties(sandbox-web PROPERTIES OUTPUT_NAME sandbox
                      RUNTIME_OUTPUT_DIRECTORY ${SANDBOX_WEB_OUT})
get_filename_component(SHIPPED_SCENES ${CMAKE_CURRENT_SOURCE_DIR}/../scenes ABSOLUTE)
get_filename_component(SHIPPED_LESSONS ${PROJECT_SOURCE_DIR}/lessons ABSOLUTE)
file(GLOB SHIPPED_SCENE_FILES CONFIGURE_DEPENDS ${SHIPPED_SCENES}/*.json ${SHIPPED_LESSONS}/*.json)
target_link_options(sandbox-web PRIVATE
  -sALLOW_MEMORY_GROWTH=1
  -lopenal
  -sEXPORTED_RUNTIME_METHODS=ccall,FS
  "SHELL:--preload-file ${SHIPPED_SCENES}@/scenes"
  "SHELL:--preload-file ${SHIPPED_LESSONS}@/lessons"
  "SHELL:--preload-file ${SANDBOX_WEB_FONT}@${SANDBOX_WEB_FONT}")
set_property(TARGET sandbox-web APPEND PROPERTY LINK_DEPENDS ${SHIPPED_SCENE_FILES})
sandbox_warnings(sandbox-web)

add_custom_command(OUTPUT ${SANDBOX_WEB_OUT}/index.html
  COMMAND ${CMAKE_COMMAND} -E copy ${WEB_DIR}/index.html ${SANDBOX_WEB_OUT}/index.html
  DEPENDS ${WEB_DIR}/index.html)
add_custom_target(sandbox-web-page ALL DEPENDS ${SANDBOX_WEB_OUT}/index.html)
