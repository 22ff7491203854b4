// Chapter 10: the trajectory CSV reads back to the recorded poses exactly.
#include <cstdlib>
#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>

#include <doctest/doctest.h>

#include "output_fixtures.hpp"
#include "stackbook/output/csv.hpp"
#include "stackbook/output/trajectory_csv.hpp"
#include "support/dimensions.hpp"

using namespace stackbook;
using namespace stackbook::testing;

namespace {

double parseDouble(const std::string& text) {
  char* end = nullptr;
  const double value = std::strtod(text.c_str(), &end);
  REQUIRE_MESSAGE(end == text.c_str() + text.size(), "not a number: '" << text << "'");
  return value;
}

template <int D>
Recording<D> csvRecording();
template <>
Recording<2> csvRecording<2>() {
  return fallingRecording2D(fewFalls(), 40, 30.0, true);
}
template <>
Recording<3> csvRecording<3>() {
  return fallingRecording3D(fewFalls(), 40, 30.0);
}

}  // namespace

TEST_SUITE(STACKBOOK_CHAPTER) {

TEST_CASE_TEMPLATE("The trajectory CSV reads back every recorded pose bit for bit", Dim, In2D, In3D) {
  constexpr int D = Dim::value;
  const Recording<D> recording = csvRecording<D>();
  const auto path = scratchFolder("csv") / "trajectory.csv";
  writeTrajectoryCsv(recording, path.string());
  const auto rows = csvRecords(readWhole(path));

  const std::vector<std::string> header =
      D == 2 ? std::vector<std::string>{"time", "body", "name", "x", "y", "angle", "vx", "vy", "omega"}
             : std::vector<std::string>{"time", "body", "name", "x", "y", "z", "qw", "qx", "qy", "qz",
                                        "vx", "vy", "vz", "wx", "wy", "wz"};
  REQUIRE(rows.size() == 1 + recording.frameCount() * recording.bodyCount());
  CHECK(rows[0] == header);
  std::size_t r = 1;
  for (std::size_t f = 0; f < recording.frameCount(); ++f) {
    for (std::size_t i = 0; i < recording.bodyCount(); ++i, ++r) {
      const auto& row = rows[r];
      REQUIRE(row.size() == header.size());
      const Pose<D>& pose = recording.poses()[f][i];
      CHECK(parseDouble(row[0]) == recording.times()[f]);
      CHECK(row[1] == std::to_string(i));
      CHECK(row[2] == recording.visuals()[i].name);  // including "ring, with a hole" in 2D
      for (int k = 0; k < D; ++k) CHECK(parseDouble(row[3 + std::size_t(k)]) == pose.position[k]);
      if constexpr (D == 2) {
        CHECK(parseDouble(row[5]) == pose.orientation.angle());
      } else {
        CHECK(parseDouble(row[6]) == pose.orientation.w());
        CHECK(parseDouble(row[7]) == pose.orientation.x());
        CHECK(parseDouble(row[8]) == pose.orientation.y());
        CHECK(parseDouble(row[9]) == pose.orientation.z());
      }
    }
  }
}

TEST_CASE("The trajectory CSV keeps doubles that need seventeen digits") {
  // 0.1 + 0.2 and 1/3 have no short decimal form; only a round-trip formatter keeps them.
  Recording<2> recording({{"odd", rectanglePolygon(Vec2(1.0, 1.0)), false, {0.5, 0.5, 0.5}}});
  Pose<2> pose;
  pose.position = Vec2(0.1 + 0.2, 1.0 / 3.0);
  pose.orientation = Eigen::Rotation2Dd(-2.0 / 3.0);
  recording.recordPoses(1e-300, {pose});
  const auto path = scratchFolder("csv17") / "odd.csv";
  writeTrajectoryCsv(recording, path.string());
  const auto rows = csvRecords(readWhole(path));
  REQUIRE(rows.size() == 2);
  CHECK(parseDouble(rows[1][0]) == 1e-300);
  CHECK(parseDouble(rows[1][3]) == 0.1 + 0.2);
  CHECK(parseDouble(rows[1][4]) == 1.0 / 3.0);
  CHECK(parseDouble(rows[1][5]) == -2.0 / 3.0);
}

TEST_CASE("Writing the CSV into a missing folder fails with the path in the message") {
  const std::string path = (scratchFolder("csvbad") / "no such folder" / "t.csv").string();
  const Recording<2> recording = fallingRecording2D(fewFalls(), 2, 30.0);
  CHECK_THROWS_WITH_AS(writeTrajectoryCsv(recording, path),
                       doctest::Contains(("cannot write '" + path + "'").c_str()), std::runtime_error);
}

TEST_CASE("CSV fields: quoted only when they must be, and read back unchanged (RFC 4180)") {
  CHECK(csvField("box") == "box");
  CHECK(csvField("box, dropped") == "\"box, dropped\"");
  CHECK(csvField("a \"b\"") == "\"a \"\"b\"\"\"");
  CHECK(csvField("two\nlines") == "\"two\nlines\"");
  // The records of a text written by hand as RFC 4180 spells it: a quoted comma, a doubled
  // quote, a line feed inside quotes, an empty field; the last line has no line feed yet.
  const std::string text = "a,\"b,c\",\"say \"\"hi\"\"\"\n\"x\ny\",,z\npartial,line";
  const auto records = csvRecords(text);
  REQUIRE(records.size() == 2);
  CHECK(records[0] == std::vector<std::string>{"a", "b,c", "say \"hi\""});
  CHECK(records[1] == std::vector<std::string>{"x\ny", "", "z"});
  // Every field csvField writes reads back as itself.
  const std::vector<std::string> fields{"plain", "", ",", "\"", "\"\"", "a,\"b\"\r\nc", "\xc3\xa9t\xc3\xa9"};
  std::string line;
  for (std::size_t k = 0; k < fields.size(); ++k) line += (k ? "," : "") + csvField(fields[k]);
  const auto back = csvRecords(line + "\n");
  REQUIRE(back.size() == 1);
  CHECK(back[0] == fields);
}

}  // TEST_SUITE
