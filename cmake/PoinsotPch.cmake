# Precompiled headers: the third-party and standard headers that most translation units include (Eigen, fmt,
# GoogleTest, CLI11, pybind11) are parsed once per target instead of once per file, which saves about 1.5–2 CPU
# seconds of each of the ~230 files in a cold build (docs/architecture.md, CI). GCC falls back to the plain
# headers wherever a precompiled one does not fit, so the result never depends on this option.
#
# POINSOT_PCH is on by default unless a compiler launcher (ccache) is set: ccache can only cache files built with
# a precompiled header under `sloppiness = pch_defines,time_macros`, which is not its default; with ccache, the
# cache is what makes rebuilds short. Turn it on or off with -DPOINSOT_PCH=ON/OFF.
set(_poinsot_pch_default ON)
if(CMAKE_CXX_COMPILER_LAUNCHER OR DEFINED ENV{CMAKE_CXX_COMPILER_LAUNCHER} OR POINSOT_FUZZ)
  set(_poinsot_pch_default OFF)
endif()
option(POINSOT_PCH "Precompiled headers for the library, the tests, the command-line tool and the Python module"
       ${_poinsot_pch_default})

# The standard headers, Eigen and fmt: what the library's sources include most (about a hundred files each).
set(POINSOT_PCH_COMMON
    <algorithm> <array> <cmath> <filesystem> <fstream> <memory> <optional> <sstream> <string> <string_view>
    <vector> <Eigen/Core> <Eigen/Eigenvalues> <Eigen/Geometry> <fmt/format.h>)

# GCC 12 reports its optimiser's flow warnings on inlined standard-library code (std::string's memcpy:
# -Warray-bounds, -Wstringop-overflow) when the library's headers come from a precompiled header, where the same
# code from the plain headers is silent (system headers). With precompiled headers these stay warnings, not
# errors; the front end's warnings (conversions, shadowing, casts) stay errors, and builds without precompiled
# headers (ccache, the default with a launcher) keep every warning an error.
set(_poinsot_pch_flow_warnings -Wno-error=array-bounds -Wno-error=stringop-overflow -Wno-error=stringop-overread
    -Wno-error=restrict -Wno-error=maybe-uninitialized)

# poinsot_precompile_headers(target [headers...]): the common headers plus the given ones, precompiled for the
# target. Files with their own compile options (the batch kernels' -ffp-contract=off) are left out, so that no
# code of theirs is parsed under other options. Call it in the directory that defines the target's sources.
function(poinsot_precompile_headers target)
  if(NOT POINSOT_PCH)
    return()
  endif()
  target_precompile_headers(${target} PRIVATE ${POINSOT_PCH_COMMON} ${ARGN})
  target_compile_options(${target} PRIVATE ${_poinsot_pch_flow_warnings})
  get_target_property(_sources ${target} SOURCES)
  foreach(src IN LISTS _sources)
    get_source_file_property(_options ${src} COMPILE_OPTIONS)
    if(_options)
      set_source_files_properties(${src} PROPERTIES SKIP_PRECOMPILE_HEADERS ON)
    endif()
  endforeach()
endfunction()

# poinsot_reuse_precompiled_headers(target from): the precompiled header of `from`, which was built with the
# same compile options and definitions (the test executables of the layers).
function(poinsot_reuse_precompiled_headers target from)
  if(POINSOT_PCH)
    target_precompile_headers(${target} REUSE_FROM ${from})
    target_compile_options(${target} PRIVATE ${_poinsot_pch_flow_warnings})
  endif()
endfunction()
