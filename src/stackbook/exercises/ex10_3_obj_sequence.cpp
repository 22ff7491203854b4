// Exercise 10.3 (your answer goes here): see ex10_3_obj_sequence.hpp and chapter 10.
// Implement: writeObjFrame and writeObjSequence. Delete every TODO(reader) comment once your
// code is in: while one is left, the exercise counts as not solved and its tests do not run.
#include "stackbook/exercises/ex10_3_obj_sequence.hpp"

namespace stackbook {

void writeObjFrame(const Recording<3>& recording, std::size_t frame, const std::string& path) {
  // TODO(reader): for each body write "o name", its vertices moved by poses()[frame][i]
  // and its faces (1-based, offset by the vertices already written).
  (void)recording;
  (void)frame;
  (void)path;
}

std::vector<std::string> writeObjSequence(const Recording<3>& recording, const std::string& directory) {
  // TODO(reader): create the directory and call writeObjFrame for every frame.
  (void)recording;
  (void)directory;
  return {};
}

}  // namespace stackbook
