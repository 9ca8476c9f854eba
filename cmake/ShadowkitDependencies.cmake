# Every dependency comes from a Debian 12 package installed by scripts/install-deps.sh.
find_package(Threads REQUIRED)
find_package(TBB REQUIRED)
find_package(embree 3 REQUIRED)
find_package(nlohmann_json 3 REQUIRED)
find_package(CLI11 REQUIRED)
find_package(PNG REQUIRED)
find_package(TinyGLTF REQUIRED)
find_package(assimp 5 REQUIRED)
find_package(absl REQUIRED)

# ERFA, the IAU SOFA astrometry routines, for the sun's position (src/scene/sun/sun_position.cpp
# says why this library); Debian's liberfa-dev installs erfa.pc and no CMake package file.
find_package(PkgConfig REQUIRED)
pkg_check_modules(ERFA REQUIRED IMPORTED_TARGET erfa)

# The viewer (shadowkit serve): cpp-httplib for HTTP, websocketpp over standalone Asio for
# its frame stream; Debian's cpp-httplib installs cpp-httplib.pc, the other two are headers.
pkg_check_modules(HTTPLIB REQUIRED IMPORTED_TARGET cpp-httplib)
find_path(WEBSOCKETPP_INCLUDE_DIR websocketpp/server.hpp REQUIRED)
find_path(ASIO_INCLUDE_DIR asio.hpp REQUIRED)

# Debian 12's OpenSubdivConfig.cmake names a static library the package does not ship,
# so the headers and libosdCPU.so are found directly.
find_path(OPENSUBDIV_INCLUDE_DIR opensubdiv/far/topologyRefiner.h REQUIRED)
find_library(OPENSUBDIV_CPU_LIBRARY NAMES osdCPU REQUIRED)
add_library(shadowkit_opensubdiv INTERFACE)
target_include_directories(shadowkit_opensubdiv SYSTEM INTERFACE ${OPENSUBDIV_INCLUDE_DIR})
target_link_libraries(shadowkit_opensubdiv INTERFACE ${OPENSUBDIV_CPU_LIBRARY})

if(SHADOWKIT_TESTS)
  find_package(GTest REQUIRED)
endif()
if(SHADOWKIT_BENCHMARKS)
  find_package(benchmark REQUIRED)
endif()
