# Modules: one folder, one static library, one list of the modules it may use.
#
#   gridcull_module(NAME culling_rgvc DIR culling/rgvc [FLAT]
#                   DEPENDS culling_api grid             # its headers include them
#                   PRIVATE_DEPENDS culling_baseline     # only its .cpp files do
#                   [LINK external targets...] [PRIVATE_LINK ...] [EXCLUDE files...])
#
# builds every .cpp under DIR (FLAT: in DIR itself, not its subfolders) into
# NAME and checks at build time (cmake/check_includes.cmake) that every
# #include in DIR's files that names a project file, quoted, in brackets or
# relative, names a file of DIR, of a module it depends on, or of a module that
# one exports through its own DEPENDS. PRIVATE_DEPENDS are not passed on: the
# registry depends privately on every family, so what depends on the registry
# still cannot include a family. That is how a family's folder is kept from
# including the oracle or another family, and the window from including a family.
#
# gridcull_check_all_built(DIR) fails the configure step when a .cpp under DIR
# belongs to no module (a file in a new folder would otherwise drop out); a
# file EXCLUDEd from a module (an executable's main) must be claimed with
# gridcull_claim_sources().
include_guard(GLOBAL)

set_property(GLOBAL PROPERTY GRIDCULL_MODULE_SOURCES "")

function(gridcull_module)
  cmake_parse_arguments(M "FLAT" "NAME;DIR"
                        "DEPENDS;PRIVATE_DEPENDS;LINK;PRIVATE_LINK;EXCLUDE" ${ARGN})
  set(glob GLOB_RECURSE)
  if(M_FLAT)
    set(glob GLOB)
  endif()
  file(${glob} sources CONFIGURE_DEPENDS ${PROJECT_SOURCE_DIR}/${M_DIR}/*.cpp)
  file(${glob} headers CONFIGURE_DEPENDS ${PROJECT_SOURCE_DIR}/${M_DIR}/*.h)
  set(checked ${sources} ${headers})  # excluded files are checked all the same
  foreach(excluded IN LISTS M_EXCLUDE)
    list(REMOVE_ITEM sources ${PROJECT_SOURCE_DIR}/${M_DIR}/${excluded})
  endforeach()
  add_library(${M_NAME} STATIC ${sources})
  target_include_directories(${M_NAME} PUBLIC ${PROJECT_SOURCE_DIR})
  target_link_libraries(${M_NAME} PUBLIC ${M_DEPENDS} ${M_LINK}
                        PRIVATE ${M_PRIVATE_DEPENDS} ${M_PRIVATE_LINK})
  set_property(GLOBAL APPEND PROPERTY GRIDCULL_MODULE_SOURCES ${sources})

  # The folders of this module's own files.
  set(own ${M_DIR})
  foreach(file IN LISTS sources headers)
    get_filename_component(folder ${file} DIRECTORY)
    file(RELATIVE_PATH folder ${PROJECT_SOURCE_DIR} ${folder})
    list(APPEND own ${folder})
  endforeach()
  list(REMOVE_DUPLICATES own)
  # What a module that depends on this one may include from it.
  set(exported ${own})
  set(allowed ${own})
  foreach(dep IN LISTS M_DEPENDS M_PRIVATE_DEPENDS)
    if(TARGET ${dep})
      get_target_property(dep_exported ${dep} GRIDCULL_EXPORTED_DIRS)
      if(dep_exported)
        list(APPEND allowed ${dep_exported})
        if(dep IN_LIST M_DEPENDS)
          list(APPEND exported ${dep_exported})
        endif()
      endif()
    endif()
  endforeach()
  list(REMOVE_DUPLICATES allowed)
  list(REMOVE_DUPLICATES exported)
  set_target_properties(${M_NAME} PROPERTIES GRIDCULL_EXPORTED_DIRS "${exported}")

  # The stamp's name carries the allowed folders, so that narrowing a module's
  # dependencies checks it again even when none of its files changed.
  string(MD5 allowed_hash "${allowed}")
  set(stamp ${CMAKE_CURRENT_BINARY_DIR}/${M_NAME}.includes-${allowed_hash}.checked)
  add_custom_command(
    OUTPUT ${stamp}
    COMMAND ${CMAKE_COMMAND} -DMODULE=${M_NAME} -DROOT=${PROJECT_SOURCE_DIR}
            "-DALLOWED=${allowed}" "-DFILES=${checked}" -DSTAMP=${stamp}
            -P ${PROJECT_SOURCE_DIR}/cmake/check_includes.cmake
    DEPENDS ${checked} ${PROJECT_SOURCE_DIR}/cmake/check_includes.cmake
    COMMENT "Checking ${M_NAME}'s includes against its dependencies"
    VERBATIM)
  add_custom_target(${M_NAME}_includes DEPENDS ${stamp})
  add_dependencies(${M_NAME} ${M_NAME}_includes)
endfunction()

function(gridcull_claim_sources)
  foreach(source IN LISTS ARGN)
    get_filename_component(absolute ${source} ABSOLUTE)
    set_property(GLOBAL APPEND PROPERTY GRIDCULL_MODULE_SOURCES ${absolute})
  endforeach()
endfunction()

function(gridcull_check_all_built dir)
  file(GLOB_RECURSE all CONFIGURE_DEPENDS ${PROJECT_SOURCE_DIR}/${dir}/*.cpp)
  get_property(built GLOBAL PROPERTY GRIDCULL_MODULE_SOURCES)
  foreach(source IN LISTS all)
    if(NOT source IN_LIST built)
      file(RELATIVE_PATH relative ${PROJECT_SOURCE_DIR} ${source})
      message(FATAL_ERROR "${relative} belongs to no module: add its folder with "
                          "gridcull_module() in ${dir}/CMakeLists.txt")
    endif()
  endforeach()
endfunction()
