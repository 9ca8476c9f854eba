// One libFuzzer target; CMake compiles this file once per target with its input kind
// (SHADOWKIT_FUZZ_KIND: "scene", "shading_groups" or a mesh extension) and whether it renders
// (SHADOWKIT_FUZZ_RENDER). See fuzz/CMakeLists.txt and docs/fuzzing.md.
#include <cstddef>
#include <cstdint>

#include "harness.h"

extern "C" int LLVMFuzzerInitialize(int* /*argc*/, char*** /*argv*/) {
  shadowkit::fuzz::initialize(SHADOWKIT_FUZZ_KIND, SHADOWKIT_FUZZ_RENDER != 0);
  return 0;
}

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  return shadowkit::fuzz::run_one(data, size);
}
