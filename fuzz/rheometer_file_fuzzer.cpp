// libFuzzer entry point for fuzz::rheometer_file (fuzz/fuzz_targets.hpp; scripts/fuzz.sh).
#include "fuzz_targets.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  dilatant::fuzz::rheometer_file(data, size);
  return 0;
}
