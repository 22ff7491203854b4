// libFuzzer target: the scene loader, with --set overrides after NUL bytes
// (stackbook::fuzz::sceneInput). A finding is an input the loader neither accepts (and
// runs a few steps of) nor refuses with one line naming the file.
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <string>

#include "support/fuzz_inputs.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string input(reinterpret_cast<const char*>(data), size);
  const std::string problem = stackbook::fuzz::sceneInput(input, STACKBOOK_FUZZ_MESH_DIR);
  if (!problem.empty()) {
    std::fprintf(stderr, "fuzz_scene: %s\n", problem.c_str());
    std::abort();
  }
  return 0;
}
