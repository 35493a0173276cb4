# Precompiled headers. Parsing the third-party headers is most of a translation unit's compile time
# here: <Eigen/Dense> alone takes about 3 s per unit with -march=native (its AVX-512 packet math),
# <gtest/gtest.h> about 2 s, and a test unit that includes solver/build.hpp spends ~5 s of its
# ~14 s on headers (GCC 12, measured 2026-11-26). CI builds the tree twice (Release, then the
# sanitized tests) on 2 cores, so each target parses these headers once instead of once per unit.
# Every listed header is one the target's units include anyway; -DSLIDELINE_PCH=OFF turns it off
# (then each unit must still compile on its own includes, which CI's other builds do not check).
option(SLIDELINE_PCH "Precompile the heavy headers of each target" ON)

# The library and the command-line program: Eigen and the standard headers nearly every unit uses.
set(SLIDELINE_PCH_LIBRARY_HEADERS
  <Eigen/Dense> <algorithm> <array> <cmath> <memory> <span> <string> <vector>)

# The test executables: gtest and the slideline headers most tests include.
set(SLIDELINE_PCH_TEST_HEADERS
  ${SLIDELINE_PCH_LIBRARY_HEADERS} <gtest/gtest.h>
  [["slideline/core/error.hpp"]] [["slideline/solver/build.hpp"]]
  [["slideline/solver/simulation.hpp"]] [["slideline/io/keyword_reader.hpp"]])

function(slideline_precompile target)
  if(SLIDELINE_PCH)
    target_precompile_headers(${target} PRIVATE ${ARGN})
  endif()
endfunction()
