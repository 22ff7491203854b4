#!/bin/sh
# Install the Debian 12 packages stackbook needs (as root, or through sudo).
#   libeigen3-dev  Eigen 3.4 (linear algebra)
#   doctest-dev    doctest 2.4.9 (tests)
#   libtinyobjloader-dev   reading OBJ meshes
#   libassimp-dev  reading STL and PLY meshes
#   libtbb-dev     oneTBB: the step's threads (chapter 10)
#   ccache         faster rebuilds (optional; changes no result)
#   nlohmann-json3-dev, libcli11-dev, libtinygltf-dev, libjs-three   the simulator: scene
#       files (JSON), the command line, animated glTF output and its offline viewer page
#   doxygen, graphviz, libjs-mathjax   the course site, with math typeset offline
#   libbox2d-dev, libbullet-dev   the peers of bench/peers_bench (Box2D 2.4, Bullet 3), optional:
#       without them the benchmark runs stackbook alone
#   gnuplot-nox    the plots of `stackbook sweep` (chapter 11's figures)
#   clang, libclang-rt-14-dev   the sanitize preset (clang's AddressSanitizer, UBSan and libFuzzer)
set -e
if [ "$(id -u)" -eq 0 ]; then SUDO=""; else SUDO="sudo"; fi
export DEBIAN_FRONTEND=noninteractive
$SUDO apt-get update -qq
$SUDO apt-get install -y -qq --no-install-recommends \
  g++ cmake make ccache libeigen3-dev doctest-dev libtinyobjloader-dev libassimp-dev libtbb-dev \
  nlohmann-json3-dev libcli11-dev libtinygltf-dev libjs-three \
  doxygen graphviz libjs-mathjax libbox2d-dev libbullet-dev gnuplot-nox \
  clang libclang-rt-14-dev >/dev/null
echo "stackbook: Debian packages installed."
