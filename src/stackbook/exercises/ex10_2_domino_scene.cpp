// Exercise 10.2 (your answer goes here): see ex10_2_domino_scene.hpp and chapter 10.
// Implement: dominoRowScene. Delete every TODO(reader) comment once your code is in: while one
// is left, the exercise counts as not solved and its tests do not run.
#include "stackbook/exercises/ex10_2_domino_scene.hpp"

namespace stackbook {

nlohmann::json dominoRowScene(const DominoRow& row) {
  // TODO(reader): write the scene as JSON: dimension, dt, duration, a "wood" material,
  // the static ground, and the dominoes (the first with an angularVelocity).
  (void)row;
  return nlohmann::json::object();
}

}  // namespace stackbook
