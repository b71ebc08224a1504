# A core stage is one folder of core/ built as one static library named clm3d_<stage>.
# Sources are the folder's own .cpp files (not subfolders), so adding a file needs no CMake edit.
function(clm3d_add_stage stage)
  cmake_parse_arguments(ARG "" "" "PUBLIC_DEPS;PRIVATE_DEPS" ${ARGN})
  file(GLOB sources CONFIGURE_DEPENDS ${CMAKE_CURRENT_SOURCE_DIR}/*.cpp)
  set(target clm3d_${stage})
  if(NOT sources)
    # A stage whose sources have not landed yet (or a header-only one): an interface library, so
    # the tree configures while a stage is being built up.
    add_library(${target} INTERFACE)
    add_library(clm3d::${stage} ALIAS ${target})
    target_include_directories(${target} INTERFACE ${PROJECT_SOURCE_DIR})
    target_link_libraries(${target} INTERFACE ${ARG_PUBLIC_DEPS} ${ARG_PRIVATE_DEPS})
    return()
  endif()
  add_library(${target} STATIC ${sources})
  add_library(clm3d::${stage} ALIAS ${target})
  target_include_directories(${target} PUBLIC ${PROJECT_SOURCE_DIR})
  target_link_libraries(${target} PUBLIC ${ARG_PUBLIC_DEPS} PRIVATE ${ARG_PRIVATE_DEPS})
  clm3d_set_warnings(${target})
endfunction()
