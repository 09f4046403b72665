# Failed writes (issue 28): every output goes to a temporary file renamed over its target when
# complete, so a write that fails exits non-zero naming the file and leaves the file that was
# there intact; an output may never be the input it was made from. CI runs as root, so the
# failures are ones root meets too: /dev/full, a directory in the way, a path under a regular file.
# -DCLI=sandbox-cli -DOFFSCREEN=sandbox-offscreen (or "") -DSCENE=a scene -DWORK=a scratch folder
get_filename_component(WORK_NAME "${WORK}" NAME)
file(REMOVE_RECURSE "${WORK}")
file(MAKE_DIRECTORY "${WORK}")
file(READ "${SCENE}" original)
file(WRITE "${WORK}/scene.json" "${original}")
file(WRITE "${WORK}/old.csv" "the old trace\n")
file(MAKE_DIRECTORY "${WORK}/dir.csv")
set(failures "")

# expect(EXIT code STDERR regex [INTACT file text] ARGS ... ) with PROGRAM cli|offscreen
function(expect program code regex)
  execute_process(COMMAND ${program} ${ARGN} RESULT_VARIABLE rc OUTPUT_VARIABLE out
    ERROR_VARIABLE err TIMEOUT 100)
  set(report "${ARGN}\nexit: ${rc}\nstderr: ${err}")
  if(NOT rc STREQUAL "${code}")
    set(failures "${failures}\nexpected exit ${code}: ${report}" PARENT_SCOPE)
  elseif(NOT err MATCHES "${regex}")
    set(failures "${failures}\nstderr does not match '${regex}': ${report}" PARENT_SCOPE)
  endif()
endfunction()

function(intact path text)
  file(READ "${path}" now)
  if(NOT now STREQUAL "${text}")
    set(failures "${failures}\n${path} was changed" PARENT_SCOPE)
  endif()
endfunction()

# The output may not be the input: the same path, another spelling of it, a link to it.
expect(${CLI} 1 "may not overwrite its input" run ${WORK}/scene.json --steps 3
  --trace ${WORK}/scene.json)
expect(${CLI} 1 "may not overwrite its input" run ${WORK}/scene.json --steps 3
  --trace ${WORK}/./../${WORK_NAME}/scene.json)
file(CREATE_LINK "${WORK}/scene.json" "${WORK}/link.json" SYMBOLIC)
expect(${CLI} 1 "may not overwrite its input" run ${WORK}/scene.json --steps 3
  --trace ${WORK}/link.json)
intact("${WORK}/scene.json" "${original}")
# A full disk, a directory in the way, a path under a regular file, a missing folder.
expect(${CLI} 1 "--trace /dev/full: cannot write \\(No space left on device\\)"
  run ${WORK}/scene.json --steps 3 --trace /dev/full)
expect(${CLI} 1 "dir\\.csv: cannot write \\(a directory is in the way\\)"
  run ${WORK}/scene.json --steps 3 --trace ${WORK}/dir.csv)
expect(${CLI} 1 "scene\\.json/t\\.csv: cannot write \\(Not a directory\\)"
  run ${WORK}/scene.json --steps 3 --trace ${WORK}/scene.json/t.csv)
expect(${CLI} 1 "missing/t\\.csv: cannot write \\(No such file or directory\\)"
  run ${WORK}/scene.json --steps 3 --trace ${WORK}/missing/t.csv)
intact("${WORK}/scene.json" "${original}")
# A good write replaces the old file and leaves no temporary file behind.
expect(${CLI} 0 "" run ${WORK}/scene.json --steps 3 --trace ${WORK}/old.csv)
file(READ "${WORK}/old.csv" trace)
if(NOT trace MATCHES "^t,")
  set(failures "${failures}\nold.csv was not replaced by the trace")
endif()
file(GLOB left "${WORK}/.*")
if(left)
  set(failures "${failures}\ntemporary files left: ${left}")
endif()

if(OFFSCREEN)
  expect(${OFFSCREEN} 2 "--screenshot: .*input file of this run" ${WORK}/scene.json
    --screenshot ${WORK}/scene.json)
  expect(${OFFSCREEN} 2 "--layout-json: .*input file of this run" ${WORK}/scene.json
    --screenshot ${WORK}/shot.png --layout-json ${WORK}/link.json)
  intact("${WORK}/scene.json" "${original}")
  expect(${OFFSCREEN} 1 "/dev/full: cannot write \\(No space left on device\\)"
    ${WORK}/scene.json --screenshot /dev/full)
  expect(${OFFSCREEN} 1 "/dev/full: cannot write \\(No space left on device\\)"
    ${WORK}/scene.json --screenshot ${WORK}/shot.png --layout-json /dev/full)
  expect(${OFFSCREEN} 1 "dir\\.csv: cannot write \\(a directory is in the way\\)"
    ${WORK}/scene.json --screenshot ${WORK}/dir.csv)
endif()

if(failures)
  message(FATAL_ERROR "${failures}")
endif()
