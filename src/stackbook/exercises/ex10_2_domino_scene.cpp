// Exercise 10.2 (your answer goes here): see ex10_2_domino_scene.hpp and chapter 10.
#include "stackbook/exercises/ex10_2_domino_scene.hpp"

namespace stackbook {

nlohmann::json dominoRowScene(const DominoRow& row) {
  // TODO(reader): write the scene as JSON: dimension, dt, duration, a "wood" material,
  // the static ground, and the dominoes (the first with an angularVelocity).
  (void)row;
  return nlohmann::json::object();
}

}  // namespace stackbook
