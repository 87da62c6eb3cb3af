# How softgrasp builds fast (doc/benchmarks.md, "Build and test times"):
# ccache shared between clones, the fastest linker installed, executables
# not relinked when only a shared library changed, and one precompiled
# header of the external libraries (deal.II, Trilinos, Boost, Eigen, the
# standard library) made once with the library and reused by every
# executable and test. Included by the top-level CMakeLists.txt after
# project().

option(SOFTGRASP_PRECOMPILED_HEADERS
  "Precompile the external headers once and reuse them in every target" ON)

# --- debug information -------------------------------------------------------
# Debian's deal.II passes its packaging flag -g to every target: in a
# Release build it makes each compilation about 1.4 times slower and each
# object file about 35 times larger (mortar_contact.cc: 19.6 against
# 14.2 s, 16 MB against 0.4 MB), and the precompiled header about 1 GB.
# Release builds drop it unless asked for; Debug builds keep deal.II's
# -ggdb.
option(SOFTGRASP_DEBUG_INFO
  "Keep deal.II's -g in Release builds (slower builds, larger files)" OFF)
if(NOT SOFTGRASP_DEBUG_INFO)
  string(REGEX REPLACE "(^| )-g( |$)" " " DEAL_II_CXX_FLAGS
    "${DEAL_II_CXX_FLAGS}")
endif()

# --- ccache ------------------------------------------------------------------
# base_dir = the source root and hash_dir off: a clone at another path (CI's
# fresh clone, a second work tree) finds the same cache entries. The
# sloppiness lets ccache cache compilations that use the precompiled header
# (ccache manual, "Precompiled headers").
find_program(CCACHE_PROGRAM ccache)
if(CCACHE_PROGRAM)
  set(CMAKE_CXX_COMPILER_LAUNCHER
    ${CMAKE_COMMAND} -E env
      CCACHE_BASEDIR=${CMAKE_SOURCE_DIR}
      CCACHE_NOHASHDIR=true
      CCACHE_SLOPPINESS=pch_defines,time_macros,include_file_mtime,include_file_ctime
      ${CCACHE_PROGRAM})
endif()

# --- linker --------------------------------------------------------------
# deal.II's flags ask for gold; mold (or else lld) links the library and the
# executables several times faster. SOFTGRASP_LINKER names the -fuse-ld
# value; empty keeps deal.II's choice.
if(NOT DEFINED SOFTGRASP_LINKER)
  find_program(SOFTGRASP_MOLD mold)
  find_program(SOFTGRASP_LLD ld.lld)
  if(SOFTGRASP_MOLD)
    set(_linker mold)
  elseif(SOFTGRASP_LLD)
    set(_linker lld)
  else()
    set(_linker "")
  endif()
  set(SOFTGRASP_LINKER "${_linker}" CACHE STRING
    "Linker for -fuse-ld= (mold, lld, gold; empty: deal.II's)")
endif()
if(SOFTGRASP_LINKER)
  include(CheckCXXSourceCompiles)
  set(CMAKE_REQUIRED_LINK_OPTIONS -fuse-ld=${SOFTGRASP_LINKER})
  check_cxx_source_compiles("int main() { return 0; }"
    SOFTGRASP_LINKER_WORKS_${SOFTGRASP_LINKER})
  unset(CMAKE_REQUIRED_LINK_OPTIONS)
  if(SOFTGRASP_LINKER_WORKS_${SOFTGRASP_LINKER})
    # deal_ii_setup_target() copies DEAL_II_LINKER_FLAGS into each target
    string(REGEX REPLACE "-fuse-ld=[a-z.]+" "" DEAL_II_LINKER_FLAGS
      "${DEAL_II_LINKER_FLAGS}")
    string(APPEND DEAL_II_LINKER_FLAGS " -fuse-ld=${SOFTGRASP_LINKER}")
    add_link_options(-fuse-ld=${SOFTGRASP_LINKER})
    message(STATUS "softgrasp: linking with ${SOFTGRASP_LINKER}")
  else()
    message(STATUS "softgrasp: -fuse-ld=${SOFTGRASP_LINKER} does not link; "
      "keeping deal.II's linker")
  endif()
endif()

# --- relinking -----------------------------------------------------------
# An edited library source relinks the library only: executables load the
# new shared library when they start. (Tests rerun all the same: their
# outputs depend on the library files, tests/CMakeLists.txt.)
set(CMAKE_LINK_DEPENDS_NO_SHARED ON)

# --- precompiled header ----------------------------------------------------
# External headers only: an edit to a softgrasp header must not rebuild
# the precompiled header and with it every file.
set(SOFTGRASP_PRECOMPILED
  <algorithm> <array> <cmath> <functional> <map> <memory> <set> <sstream>
  <string> <vector>
  <Eigen/Core> <Eigen/Geometry>
  <deal.II/base/conditional_ostream.h> <deal.II/base/function.h>
  <deal.II/base/index_set.h> <deal.II/base/mpi.h>
  <deal.II/base/parameter_handler.h> <deal.II/base/point.h>
  <deal.II/base/quadrature_lib.h> <deal.II/base/symmetric_tensor.h>
  <deal.II/base/tensor.h> <deal.II/base/timer.h> <deal.II/base/utilities.h>
  <deal.II/distributed/tria.h>
  <deal.II/dofs/dof_handler.h> <deal.II/dofs/dof_tools.h>
  <deal.II/fe/fe_q.h> <deal.II/fe/fe_system.h> <deal.II/fe/fe_values.h>
  <deal.II/fe/mapping_q.h>
  <deal.II/grid/grid_generator.h> <deal.II/grid/grid_tools.h>
  <deal.II/grid/tria.h>
  <deal.II/lac/affine_constraints.h> <deal.II/lac/full_matrix.h>
  <deal.II/lac/la_parallel_vector.h> <deal.II/lac/trilinos_sparse_matrix.h>
  <deal.II/lac/trilinos_vector.h> <deal.II/lac/vector.h>
  <deal.II/numerics/data_out.h> <deal.II/numerics/vector_tools.h>
  <deal.II/physics/transformations.h>)

# The library makes the precompiled header (lib/CMakeLists.txt); every
# other C++ target below @p directory reuses it. Executables and tests have
# the library's compiler flags (deal.II's, -march=native), which a
# precompiled header requires; GCC checks this and, with -Winvalid-pch,
# says so and parses the headers instead.
function(softgrasp_reuse_precompiled_header directory)
  if(NOT SOFTGRASP_PRECOMPILED_HEADERS)
    return()
  endif()
  get_property(targets DIRECTORY ${directory} PROPERTY BUILDSYSTEM_TARGETS)
  foreach(target ${targets})
    get_property(type TARGET ${target} PROPERTY TYPE)
    if(NOT target STREQUAL "softgrasp" AND
        type MATCHES "^(EXECUTABLE|SHARED_LIBRARY|STATIC_LIBRARY)$")
      target_precompile_headers(${target} REUSE_FROM softgrasp)
    endif()
  endforeach()
  get_property(subdirectories DIRECTORY ${directory} PROPERTY SUBDIRECTORIES)
  foreach(subdirectory ${subdirectories})
    softgrasp_reuse_precompiled_header(${subdirectory})
  endforeach()
endfunction()
