# The x86-64 level a Release build targets, SHADOWKIT_MARCH. "auto" takes the highest level the
# building machine runs: x86-64-v3 (AVX2, FMA) lets the compiler vectorize the scan
# converter's spans four doubles wide instead of two. Results do not depend on the level:
# -ffp-contract=off (ShadowkitWarnings.cmake) keeps FMA from fusing any multiply and add.
set(SHADOWKIT_ARCH "auto" CACHE STRING
    "-march of Release builds: auto (x86-64-v3 where the building CPU runs it, else x86-64-v2) or a value for -march, e.g. x86-64-v2 for a binary that runs on older CPUs")

if(SHADOWKIT_ARCH STREQUAL "auto")
  try_run(shadowkit_v3_runs shadowkit_v3_compiles
    SOURCE_FROM_CONTENT cpu_level.cpp
    "int main() { __builtin_cpu_init(); return __builtin_cpu_supports(\"x86-64-v3\") ? 0 : 1; }")
  if(shadowkit_v3_compiles AND shadowkit_v3_runs EQUAL 0)
    set(SHADOWKIT_MARCH x86-64-v3)
  else()
    set(SHADOWKIT_MARCH x86-64-v2)
  endif()
else()
  set(SHADOWKIT_MARCH ${SHADOWKIT_ARCH})
endif()
# For the benchmark pages, which name the build (scripts/benchmarks.sh).
set(SHADOWKIT_MARCH ${SHADOWKIT_MARCH} CACHE INTERNAL "-march of Release builds")
if(CMAKE_BUILD_TYPE STREQUAL "Release")
  message(STATUS "shadowkit: Release build for -march=${SHADOWKIT_MARCH}")
endif()
