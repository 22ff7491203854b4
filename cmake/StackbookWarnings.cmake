# One interface target carries the project's compile options, so every target
# (library, tests, examples, solutions) is built with the same flags.
add_library(stackbook_options INTERFACE)
target_compile_options(stackbook_options INTERFACE
  -Wall -Wextra -Wpedantic -Wshadow -Wconversion -Wno-sign-conversion
  # Determinism: no fused multiply-add contraction, so results do not depend on
  # what the optimiser chose to fuse (same scene, same settings, same bits).
  -ffp-contract=off)
if(STACKBOOK_WERROR)
  target_compile_options(stackbook_options INTERFACE -Werror)
endif()
if(STACKBOOK_SANITIZE)
  target_compile_options(stackbook_options INTERFACE
    -fsanitize=address,undefined -fno-sanitize-recover=all -fno-omit-frame-pointer)
  target_link_options(stackbook_options INTERFACE -fsanitize=address,undefined)
endif()
