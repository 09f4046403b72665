# The benchmark's pipelined frames (frame N+1 worked out on a second thread while frame N is
# drawn, as the window's loop does: app/gui/platform/frame) against the same frames worked out
# and drawn in turn (--benchmark-in-turn): the last frame's PNG byte for byte, twice. The last
# frame is drawn while the worker works out the one after it, as every other: without ImGui's
# draw data copied, or with one frame's buffers for both threads, the PNGs differ. The overlays are those whose
# numbers do not depend on the machine's speed (not the side-by-side table's ms per step).
# Run: cmake -DOFFSCREEN=... -DSCENE=... -DOUT=... -P check_benchmark_pipeline.cmake
file(MAKE_DIRECTORY ${OUT})
set(args ${SCENE} --benchmark-frames 60 --size 640x360
    --show plots,vectors,trails,inspector,com,poi,timeline)
function(shoot name)
  execute_process(COMMAND ${OFFSCREEN} ${args} ${ARGN} --screenshot ${OUT}/${name}.png
                  RESULT_VARIABLE code OUTPUT_VARIABLE out ERROR_VARIABLE err)
  if(NOT code EQUAL 0)
    message(FATAL_ERROR "${name}: exit ${code}\n${out}\n${err}")
  endif()
endfunction()
shoot(in_turn --benchmark-in-turn)
foreach(run 1 2)
  shoot(pipelined_${run})
  execute_process(COMMAND ${CMAKE_COMMAND} -E compare_files ${OUT}/in_turn.png
                          ${OUT}/pipelined_${run}.png RESULT_VARIABLE differ)
  if(NOT differ EQUAL 0)
    message(FATAL_ERROR "run ${run}: the pipelined benchmark's last frame differs from the one "
                        "drawn in turn (${OUT})")
  endif()
endforeach()
