// libFuzzer entry point for fuzz::config (fuzz/fuzz_targets.hpp; scripts/fuzz.sh).
#include "fuzz_targets.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  dilatant::fuzz::config(data, size);
  return 0;
}
