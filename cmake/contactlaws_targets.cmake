# Helpers of the top CMakeLists: the warning flags of every target, the
# library's layers, and the check that a layer stays free of MuJoCo.

# The warnings of every target of this project, tests included: link
# contactlaws_warnings PRIVATE (never exported).
add_library(contactlaws_warnings INTERFACE)
if(CMAKE_CXX_COMPILER_ID MATCHES "GNU|Clang")
  target_compile_options(contactlaws_warnings INTERFACE -Wall -Wextra -Wpedantic)
endif()

# contactlaws_add_layer(LAYER [WITHOUT_MUJOCO] [DEPENDS TARGETS...]): the
# sources of src/LAYER as the object library contactlaws_LAYER, which sees
# include/ and src/ and links DEPENDS publicly. WITHOUT_MUJOCO: refuse a
# MuJoCo, fmt or Eigen header reached from the layer (contactlaws_check_layer).
function(contactlaws_add_layer layer)
  cmake_parse_arguments(PARSE_ARGV 1 arg "WITHOUT_MUJOCO" "" "DEPENDS")
  set(name contactlaws_${layer})
  file(GLOB sources CONFIGURE_DEPENDS "${PROJECT_SOURCE_DIR}/src/${layer}/*.cc")
  add_library(${name} OBJECT ${sources})
  target_link_libraries(${name} PUBLIC ${arg_DEPENDS})
  if(arg_WITHOUT_MUJOCO)
    contactlaws_check_layer(src/${layer})
  endif()
  target_compile_features(${name} PUBLIC cxx_std_17)
  target_include_directories(${name} PUBLIC
    $<BUILD_INTERFACE:${PROJECT_SOURCE_DIR}/include>
    $<BUILD_INTERFACE:${PROJECT_SOURCE_DIR}/src>)
  target_link_libraries(${name} PRIVATE contactlaws_warnings)
  set_target_properties(${name} PROPERTIES POSITION_INDEPENDENT_CODE ON)
endfunction()

# Headers a MuJoCo-free layer (laws, memory) must not reach, directly or
# through the project's own headers it includes, and why.
set(contactlaws_forbidden_includes "mujoco/" "fmt/" "Eigen/")
set(contactlaws_forbidden_reason "this layer is built without MuJoCo, fmt and Eigen")

# Follows the #include lines of file, recording in the parent's
# contactlaws_visited the files seen; fails on a forbidden header.
function(contactlaws_check_includes file origin)
  if(file IN_LIST contactlaws_visited)
    return()
  endif()
  list(APPEND contactlaws_visited "${file}")
  set(contactlaws_visited "${contactlaws_visited}" PARENT_SCOPE)
  file(STRINGS "${file}" lines REGEX "^#include [<\"]")
  foreach(line IN LISTS lines)
    string(REGEX REPLACE "^#include [<\"]([^>\"]+)[>\"].*" "\\1" header "${line}")
    foreach(forbidden IN LISTS contactlaws_forbidden_includes)
      string(FIND "${header}" "${forbidden}" at)
      if(at EQUAL 0)
        message(FATAL_ERROR "${origin} reaches <${header}> (through ${file}): "
                            "${contactlaws_forbidden_reason}")
      endif()
    endforeach()
    foreach(root "${PROJECT_SOURCE_DIR}/include" "${PROJECT_SOURCE_DIR}/src")
      if(EXISTS "${root}/${header}")
        contactlaws_check_includes("${root}/${header}" "${origin}")
        set(contactlaws_visited "${contactlaws_visited}" PARENT_SCOPE)
      endif()
    endforeach()
  endforeach()
endfunction()

# contactlaws_check_layer(DIR): every source and header of DIR is free of the
# forbidden headers, through everything of the project it includes.
function(contactlaws_check_layer dir)
  file(GLOB files "${PROJECT_SOURCE_DIR}/${dir}/*.cc" "${PROJECT_SOURCE_DIR}/${dir}/*.h")
  set(contactlaws_visited "")
  foreach(file IN LISTS files)
    contactlaws_check_includes("${file}" "${file}")
  endforeach()
endfunction()

# contactlaws_check_beside_cli(DIR): every source and header of DIR (a
# front-end: python/) reaches neither the command line's headers (src/cli)
# nor CLI11's, directly or through the project's headers: the two
# front-ends stand side by side over the application layer (src/app).
function(contactlaws_check_beside_cli dir)
  set(contactlaws_forbidden_includes "cli/" "CLI/")
  set(contactlaws_forbidden_reason
      "a front-end beside the command line uses the application layer (src/app), not src/cli")
  file(GLOB files "${dir}/*.cc" "${dir}/*.h")
  set(contactlaws_visited "")
  foreach(file IN LISTS files)
    contactlaws_check_includes("${file}" "${file}")
  endforeach()
endfunction()
