// Prints, as Markdown, the cost table of chapter 6: the benchmark bench/sdf_grid_bench.cpp
// up to 64 cells (128 in 2D), one build per entry so that the docs build stays quick.
// The times are those of the machine that builds the course.
#define STACKBOOK_BENCH_NO_MAIN
#include "../../bench/sdf_grid_bench.cpp"

int main() {
  runSdfGridBench(64, 1);
  return 0;
}
