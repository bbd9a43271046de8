// libFuzzer entry point for fuzz::predict_tables (fuzz/fuzz_targets.hpp; scripts/fuzz.sh).
#include "fuzz_targets.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  dilatant::fuzz::predict_tables(data, size);
  return 0;
}
