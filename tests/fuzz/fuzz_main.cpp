// The libFuzzer entry point of one fuzz target, chosen when it is compiled:
// LOOM_FUZZ_TARGET is fuzz_obj, fuzz_rules, ... (tests/fuzz/CMakeLists.txt).
#include "tests/fuzz/fuzz_targets.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  return loom::fuzz::LOOM_FUZZ_TARGET(data, size);
}
