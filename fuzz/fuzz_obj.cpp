// libFuzzer target: the OBJ loader, strict and in repair mode (stackbook::fuzz::objInput).
// A finding is an input that ends in anything but a mesh or a refusal.
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <string>

#include "support/fuzz_inputs.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string input(reinterpret_cast<const char*>(data), size);
  const std::string problem = stackbook::fuzz::objInput(input);
  if (!problem.empty()) {
    std::fprintf(stderr, "fuzz_obj: %s\n", problem.c_str());
    std::abort();
  }
  return 0;
}
