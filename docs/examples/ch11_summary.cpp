// Chapter 11's summary (\include{doc} ch11_summary.out): for every scene of the chapter's sweeps,
// each error measure and each accuracy the sweeps ask for, the cheapest stackbook setting and the
// cheapest peer run that reach it, over every sweep of that scene. It reads the CSVs the docs
// build has just made or copied into doc_out/figures/sweeps/ (STACKBOOK_SWEEPS_OUT), one per spec
// of docs/sweeps/, so every number in it is a row of a sweep; a spec without its CSV is an error.
#include <algorithm>
#include <cstdio>
#include <filesystem>
#include <string>
#include <vector>

#include "stackbook/scene/sweep.hpp"

using namespace stackbook;
namespace fs = std::filesystem;

int main() {
  std::vector<std::string> files;
  for (const auto& entry : fs::directory_iterator("docs/sweeps")) {
    const std::string name = entry.path().filename().string();
    if (name.size() > 11 && name.ends_with("_sweep.json")) files.push_back(entry.path().string());
  }
  std::sort(files.begin(), files.end());
  std::vector<SweepSpec> specs;
  std::vector<std::string> csvs;
  for (const std::string& file : files) {
    specs.push_back(loadSweepSpec(file));
    const fs::path csv = fs::path(STACKBOOK_SWEEPS_OUT) / (specs.back().name + ".csv");
    if (!fs::exists(csv)) {
      std::fprintf(stderr, "ch11_summary: %s has no CSV at %s\n", file.c_str(), csv.string().c_str());
      return 1;
    }
    csvs.push_back(csv.string());
  }
  std::fputs(sweepSummaryTable(specs, csvs).c_str(), stdout);
  return 0;
}
