# Modules: one folder, one static library, one list of the modules it may use.
#
#   gridcull_module(NAME culling_rgvc DIR culling/rgvc
#                   DEPENDS culling_api culling_baseline grid
#                   [LINK external targets...] [PRIVATE_LINK ...] [EXCLUDE files...])
#
# builds every .cpp under DIR (recursively) into NAME, links DEPENDS, and checks
# at build time that every project #include "..." in DIR's files names a file of
# DIR or of a module it depends on (directly or through its dependencies), so
# that, say, an algorithm family cannot include the oracle or another family.
# gridcull_check_all_built(DIR) fails the configure step when a .cpp under DIR
# belongs to no module (a file in a new folder would otherwise drop out); a
# file EXCLUDEd from a module (an executable's main) must be claimed with
# gridcull_claim_sources().
include_guard(GLOBAL)

set_property(GLOBAL PROPERTY GRIDCULL_MODULE_SOURCES "")

function(gridcull_module)
  cmake_parse_arguments(M "" "NAME;DIR" "DEPENDS;LINK;PRIVATE_LINK;EXCLUDE" ${ARGN})
  file(GLOB_RECURSE sources CONFIGURE_DEPENDS ${PROJECT_SOURCE_DIR}/${M_DIR}/*.cpp)
  foreach(excluded IN LISTS M_EXCLUDE)
    list(REMOVE_ITEM sources ${PROJECT_SOURCE_DIR}/${M_DIR}/${excluded})
  endforeach()
  file(GLOB_RECURSE headers CONFIGURE_DEPENDS ${PROJECT_SOURCE_DIR}/${M_DIR}/*.h)
  add_library(${M_NAME} STATIC ${sources})
  target_include_directories(${M_NAME} PUBLIC ${PROJECT_SOURCE_DIR})
  target_link_libraries(${M_NAME} PUBLIC ${M_DEPENDS} ${M_LINK} PRIVATE ${M_PRIVATE_LINK})
  set_property(GLOBAL APPEND PROPERTY GRIDCULL_MODULE_SOURCES ${sources})

  # The folders this module may include from: its own and its dependencies'.
  set(allowed ${M_DIR})
  foreach(dep IN LISTS M_DEPENDS)
    if(TARGET ${dep})
      get_target_property(dep_allowed ${dep} GRIDCULL_ALLOWED_DIRS)
      if(dep_allowed)
        list(APPEND allowed ${dep_allowed})
      endif()
    endif()
  endforeach()
  list(REMOVE_DUPLICATES allowed)
  set_target_properties(${M_NAME} PROPERTIES GRIDCULL_ALLOWED_DIRS "${allowed}")

  set(stamp ${CMAKE_CURRENT_BINARY_DIR}/${M_NAME}.includes-checked)
  add_custom_command(
    OUTPUT ${stamp}
    COMMAND ${CMAKE_COMMAND} -DMODULE=${M_NAME} -DROOT=${PROJECT_SOURCE_DIR}
            "-DALLOWED=${allowed}" "-DFILES=${sources};${headers}" -DSTAMP=${stamp}
            -P ${PROJECT_SOURCE_DIR}/cmake/check_includes.cmake
    DEPENDS ${sources} ${headers} ${PROJECT_SOURCE_DIR}/cmake/check_includes.cmake
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
