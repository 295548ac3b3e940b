# Run by gridcull_module() at build time (cmake -P): every #include, quoted or
# in angle brackets, in FILES that names a file of the project (resolved against
# the including file's folder first, then ROOT, as the compiler does) must name
# one whose folder is one of ALLOWED. A relative include ("../x/y.h") is checked
# by the folder it resolves to. Includes of other files (a library's headers)
# are not checked. On success writes STAMP; otherwise lists each offending line
# and fails.
cmake_minimum_required(VERSION 3.20)
set(problems "")
foreach(file IN LISTS FILES)
  if(NOT file)
    continue()
  endif()
  get_filename_component(here ${file} DIRECTORY)
  file(STRINGS ${file} lines REGEX "^[ \t]*#[ \t]*include[ \t]*[<\"][^>\"]+[>\"]")
  foreach(line IN LISTS lines)
    string(REGEX REPLACE "^[ \t]*#[ \t]*include[ \t]*[<\"]([^>\"]+)[>\"].*" "\\1" included "${line}")
    # Where the compiler finds it: beside the including file (quoted form), or
    # under the project root, which every module has on its include path.
    set(target "")
    if(line MATCHES "\"" AND EXISTS ${here}/${included})
      get_filename_component(target ${here}/${included} ABSOLUTE)
    elseif(EXISTS ${ROOT}/${included})
      get_filename_component(target ${ROOT}/${included} ABSOLUTE)
    endif()
    if(NOT target)
      continue()  # not a project file
    endif()
    file(RELATIVE_PATH relative_target ${ROOT} ${target})
    if(relative_target MATCHES "^\\.\\./")
      continue()  # outside the project
    endif()
    get_filename_component(folder ${relative_target} DIRECTORY)
    if(NOT folder IN_LIST ALLOWED)
      file(RELATIVE_PATH relative ${ROOT} ${file})
      string(STRIP "${line}" shown)
      string(APPEND problems "  ${relative}: ${shown}\n")
    endif()
  endforeach()
endforeach()
if(problems)
  string(REPLACE ";" ", " allowed_text "${ALLOWED}")
  message(FATAL_ERROR "${MODULE} includes from folders it does not depend on:\n${problems}"
                      "It may include from: ${allowed_text}.\n"
                      "Depend on the module in its gridcull_module() call, or move the code.")
endif()
file(WRITE ${STAMP} "ok\n")
