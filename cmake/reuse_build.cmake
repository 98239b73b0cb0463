# Included by CMakeLists.txt when BONL_REUSE_BUILD names a built bonl build folder: bonl::plant and
# bonl::experiment become that folder's static libraries (the targets it exported,
# <folder>/bonlPlantTargets.cmake and bonlExperimentTargets.cmake) instead of being compiled again.
# scripts/test.sh builds the Python extension so, against build/ci, which it has just built: the
# libraries are position-independent, and built from the same sources by the same compiler, which
# is checked here. The reused folder is not rebuilt from here: build it first.
get_filename_component(BONL_REUSE_BUILD "${BONL_REUSE_BUILD}" ABSOLUTE)
load_cache("${BONL_REUSE_BUILD}" READ_WITH_PREFIX bonl_reused_ bonl_SOURCE_DIR CMAKE_CXX_COMPILER CMAKE_BUILD_TYPE)
if(NOT bonl_reused_bonl_SOURCE_DIR STREQUAL PROJECT_SOURCE_DIR)
  message(FATAL_ERROR "BONL_REUSE_BUILD: ${BONL_REUSE_BUILD} is not a bonl build of ${PROJECT_SOURCE_DIR} "
                      "(its source folder: '${bonl_reused_bonl_SOURCE_DIR}')")
endif()
# Compared through their symbolic links: /usr/bin/c++ and /usr/bin/g++ may both be g++-12.
get_filename_component(bonl_reused_compiler "${bonl_reused_CMAKE_CXX_COMPILER}" REALPATH)
get_filename_component(bonl_compiler "${CMAKE_CXX_COMPILER}" REALPATH)
if(NOT bonl_reused_compiler STREQUAL bonl_compiler)
  message(FATAL_ERROR "BONL_REUSE_BUILD: ${BONL_REUSE_BUILD} was compiled by ${bonl_reused_CMAKE_CXX_COMPILER}, "
                      "this build compiles with ${CMAKE_CXX_COMPILER}")
endif()
foreach(export_set IN ITEMS bonlPlantTargets bonlExperimentTargets)
  if(NOT EXISTS "${BONL_REUSE_BUILD}/${export_set}.cmake")
    message(FATAL_ERROR "BONL_REUSE_BUILD: no ${BONL_REUSE_BUILD}/${export_set}.cmake (configure and build it first)")
  endif()
  include("${BONL_REUSE_BUILD}/${export_set}.cmake")
endforeach()
message(STATUS "bonl: linking bonl_plant and bonl_experiment of ${BONL_REUSE_BUILD} "
               "(${bonl_reused_CMAKE_BUILD_TYPE}), not compiling them")
