# The one-file build's page (cmake -P): index.html with the script between its markers replaced
# by the single-file sandbox.js itself (the wasm and the data inside it, base64), and the page
# told it is the one-file build.
#   cmake -DPAGE=index.html -DSCRIPT=sandbox-offline.js -DOUT=sandbox-offline.html -P one_file.cmake
file(READ "${PAGE}" page)
file(READ "${SCRIPT}" script)
set(begin "<!-- sandbox.js: the one-file build has the script itself from here -->")
set(end "<!-- to here -->")
string(FIND "${page}" "${begin}" at)
string(FIND "${page}" "${end}" to)
set(flag "window.sandboxOneFile = false;")
string(FIND "${page}" "${flag}" flagAt)
if(at EQUAL -1 OR to EQUAL -1 OR flagAt EQUAL -1)
  message(FATAL_ERROR "${PAGE}: the one-file markers are missing")
endif()
# "</script" inside the script would end the inline <script> early; "<\/script" means the same
# in JavaScript's strings and regular expressions.
string(REPLACE "</script" "<\\/script" script "${script}")
string(SUBSTRING "${page}" 0 ${at} head)
string(LENGTH "${end}" endLength)
math(EXPR tail "${to} + ${endLength}")
string(SUBSTRING "${page}" ${tail} -1 rest)
string(REPLACE "${flag}" "window.sandboxOneFile = true;" head "${head}")
file(WRITE "${OUT}" "${head}<script>\n${script}\n</script>${rest}")
