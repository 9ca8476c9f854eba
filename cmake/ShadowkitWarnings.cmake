# One interface target carries the project's warnings and sanitizer flags.
add_library(shadowkit_warnings INTERFACE)
target_compile_options(shadowkit_warnings INTERFACE
  -Wall -Wextra -Wpedantic -Wshadow -Wnon-virtual-dtor -Wold-style-cast -Wcast-align
  -Woverloaded-virtual -Wnull-dereference -Wimplicit-fallthrough
  # GCC 12 reports false positives inside std::string (GCC bug 105329); clang has no such switch.
  $<$<CXX_COMPILER_ID:GNU>:-Wno-restrict>)
if(SHADOWKIT_WARNINGS_AS_ERRORS)
  target_compile_options(shadowkit_warnings INTERFACE -Werror)
endif()

add_library(shadowkit_options INTERFACE)
target_link_libraries(shadowkit_options INTERFACE shadowkit_warnings)
# No code reads errno after a math function; without the flag std::sqrt keeps a branch to
# set it, and no loop that takes a square root is vectorized. No multiply and add fused into
# one FMA either: every build, whatever its -march, rounds every operation alike, so masks and
# counts are the same bit for bit.
target_compile_options(shadowkit_options INTERFACE -fno-math-errno -ffp-contract=off)
if(CMAKE_BUILD_TYPE STREQUAL "Release")
  target_compile_options(shadowkit_options INTERFACE -march=${SHADOWKIT_MARCH} -O3)
endif()
if(SHADOWKIT_SANITIZE)
  target_compile_options(shadowkit_options INTERFACE
    -fsanitize=address,undefined -fno-omit-frame-pointer -fno-sanitize-recover=undefined)
  target_link_options(shadowkit_options INTERFACE -fsanitize=address,undefined)
  # GCC's flow analysis under ASan reports uninitialised reads inside libstdc++ (std::regex's
  # std::function states) that are not there; its manual warns of such false positives.
  target_compile_options(shadowkit_warnings INTERFACE
    $<$<CXX_COMPILER_ID:GNU>:-Wno-maybe-uninitialized>)
endif()
