// Prints, as a Markdown table, how often a 17-digit decimal (enough to identify a double)
// comes back changed when tinyobjloader parses it, against strtod (chapter 6, Pitfalls):
// why the OBJ loader reads vertex coordinates itself.
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <random>
#include <sstream>
#include <vector>

// tinyobjloader in double precision, as the library builds it.
#define TINYOBJLOADER_USE_DOUBLE
#include <tiny_obj_loader.h>

namespace {

void objRoundingRow() {
  // 20000 random doubles in [-1, 1], written with 17 significant digits (enough to
  // identify a double), read back by tinyobjloader's parser and by strtod.
  std::mt19937_64 engine(7);
  std::vector<double> values;
  std::ostringstream text;
  text.precision(17);
  for (int i = 0; i < 20000; ++i) {
    const double x = -1.0 + 2.0 * static_cast<double>(engine() >> 11) * 0x1.0p-53;
    values.push_back(x);
    text << "v " << x << " 0 0\n";
  }
  tinyobj::ObjReader reader;
  reader.ParseFromString(text.str(), "");
  const std::vector<tinyobj::real_t>& parsed = reader.GetAttrib().vertices;
  int changedTiny = 0, changedStrtod = 0;
  double worstUlp = 0.0;
  for (std::size_t i = 0; i < values.size(); ++i) {
    std::ostringstream one;
    one.precision(17);
    one << values[i];
    if (std::strtod(one.str().c_str(), nullptr) != values[i]) ++changedStrtod;
    if (parsed[3 * i] != values[i]) {
      ++changedTiny;
      const double ulp = std::nextafter(std::abs(values[i]), 2.0) - std::abs(values[i]);
      worstUlp = std::max(worstUlp, std::abs(parsed[3 * i] - values[i]) / ulp);
    }
  }
  std::printf("| tinyobjloader | %d of %zu | %.0f |\n", changedTiny, values.size(), worstUlp);
  std::printf("| strtod | %d of %zu | 0 |\n", changedStrtod, values.size());
}

}  // namespace

int main() {
  std::printf("| parser | values changed | worst error (units in the last place) |\n");
  std::printf("|---|---|---|\n");
  objRoundingRow();
  return 0;
}
