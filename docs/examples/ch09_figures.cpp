// Chapter 9's figures, computed with worldContactGraph and topologicalLevels on the plank
// lying across two stacks (ground 0; a stack of two boxes 1, 2; a stack of four 3-6; the
// plank 7): the scene with each body coloured by its level, and the contact graph as a
// Graphviz file (one row per level) that the page draws with \dotfile.
#include <array>
#include <fstream>
#include <iostream>
#include <string>

#include "../../tests/ch09/stack_scenes.hpp"
#include "figure_svg.hpp"
#include "stackbook/stacking/level_summary.hpp"

using namespace stackbook;
using namespace figure_svg;

namespace {

const std::array<const char*, 8> kLevelColours = {"#bbbbbb", "#a6cee3", "#b2df8a", "#fdbf6f",
                                                   "#cab2d6", "#fb9a99", "#ffff99", "#8dd3c7"};

const char* levelColour(int level) {
  return kLevelColours[static_cast<std::size_t>(level) % kLevelColours.size()];
}

void scenePicture(const World<2>& world, const ContactLevels& levels) {
  Svg svg(640, 330, "The plank on two stacks, each body coloured by its level in the contact graph");
  const View v = View::equal(20, 20, 600, 270, -1.6, 1.6, -0.25, 1.35);
  for (int b = 0; b < world.size(); ++b) {
    const RigidBody<2>& body = world.bodies[static_cast<std::size_t>(b)];
    const Aabb<2> box = world.shapes[static_cast<std::size_t>(b)]->bounds();
    Points corners;
    for (const Vec2& c : {Vec2(box.lower.x(), box.lower.y()), Vec2(box.upper.x(), box.lower.y()),
                          Vec2(box.upper.x(), box.upper.y()), Vec2(box.lower.x(), box.upper.y())}) {
      Vec2 w = body.position + body.orientation * c;
      w.x() = std::clamp(w.x(), -1.6, 1.6);  // the ground is wider than the picture
      w.y() = std::max(w.y(), -0.25);
      corners.emplace_back(w.x(), w.y());
    }
    const int level = levels.levelOfBody[static_cast<std::size_t>(b)];
    svg.polygon(v, corners, filled(levelColour(level), "#333", 1.2));
    // The ground and the plank are wide: one line. A box is narrower than "body 1, level 1":
    // its body and its level on two lines.
    const std::string body_name = "body " + std::to_string(b), level_name = "level " + std::to_string(level);
    if (b == 0 || box.upper.x() - box.lower.x() > 1.0) {
      const double labelY = b == 0 ? -0.12 : body.position.y();
      svg.text(v, body.position.x(), labelY, body_name + ", " + level_name, "middle", 0, 5, "#111", 12);
    } else {
      svg.text(v, body.position.x(), body.position.y(), body_name, "middle", 0, -2, "#111", 12);
      svg.text(v, body.position.x(), body.position.y(), level_name, "middle", 0, 12, "#111", 12);
    }
  }
  svg.save("ch09_plank_levels.svg");
}

void graphFile(const ContactGraph& graph, const ContactLevels& levels) {
  const std::string path = std::string(STACKBOOK_FIGURES_DIR) + "/ch09_contact_graph.dot";
  std::ofstream dot(path);
  dot << "digraph contact_graph {\n"
      << "  rankdir=BT; ranksep=0.25; node [shape=box, style=\"rounded,filled\", fontname=\"Helvetica\"];\n"
      << "  edge [color=\"#555555\"];\n";
  for (int l = 0; l < static_cast<int>(levels.levelCount()); ++l) {
    dot << "  subgraph level_" << l << " { rank=same; level_label_" << l << " [shape=plaintext, style=\"\", label=\"level "
        << l << "\"];";
    for (std::size_t k = levels.bodyStart[static_cast<std::size_t>(l)];
         k < levels.bodyStart[static_cast<std::size_t>(l) + 1]; ++k) {
      const int b = levels.bodyList[k];
      dot << " b" << b << " [label=\"" << (b == 0 ? "ground 0" : b == 7 ? "plank 7" : "box " + std::to_string(b))
          << "\", fillcolor=\"" << levelColour(l) << "\"];";
    }
    dot << " }\n";
    if (l > 0) dot << "  level_label_" << l - 1 << " -> level_label_" << l << " [style=invis];\n";
  }
  for (const ContactPair& e : graph.edges()) dot << "  b" << e.below << " -> b" << e.above << ";\n";
  dot << "}\n";
  if (!dot) throw std::runtime_error("cannot write " + path);
  std::cout << "ch09_contact_graph.dot: " << graph.edgeCount() << " edges, " << levels.levelCount()
            << " levels\n";
}

}  // namespace

int main() {
  const Material material{0.0, 0.5, 0.0};
  const World<2> world = stacks::plankOnTwoStacks<2>(material);
  const ContactGraph graph = worldContactGraph<2>(world, ContactGraphSettings{});
  const ContactLevels levels = topologicalLevels(graph);
  scenePicture(world, levels);
  graphFile(graph, levels);
}
