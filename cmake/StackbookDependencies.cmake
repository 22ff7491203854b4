# Every dependency is a Debian package. A missing one stops the configure step
# and names the package to install (see README.md, "Quick start").
function(stackbook_require_package name apt_package)
  find_package(${name} ${ARGN} QUIET)
  if(NOT ${name}_FOUND)
    message(FATAL_ERROR
      "stackbook needs ${name}, which was not found.\n"
      "On Debian 12 install it with:  apt-get install ${apt_package}\n"
      "(or run: sh .ci/install-deps.sh, which installs everything stackbook uses)")
  endif()
endfunction()

stackbook_require_package(Eigen3 libeigen3-dev 3.4 NO_MODULE)
stackbook_require_package(doctest doctest-dev 2.4)
include(/usr/lib/cmake/doctest/doctest.cmake OPTIONAL RESULT_VARIABLE _doctest_cmake)
if(NOT _doctest_cmake)
  find_file(STACKBOOK_DOCTEST_CMAKE doctest.cmake PATHS ${doctest_DIR} NO_DEFAULT_PATH)
  if(NOT STACKBOOK_DOCTEST_CMAKE)
    message(FATAL_ERROR "doctest.cmake (doctest_discover_tests) not found; apt-get install doctest-dev")
  endif()
  include(${STACKBOOK_DOCTEST_CMAKE})
endif()
# OBJ meshes (chapter 6): tinyobjloader built with double-precision reals.
stackbook_require_package(tinyobjloader libtinyobjloader-dev)
# STL and PLY meshes (chapter 6): assimp reads them, stackbook checks and repairs them.
stackbook_require_package(assimp libassimp-dev)
# Debian's assimp target lists libdraco among its link libraries, and libdraco exports its own
# build of tinygltf's functions: named on a link line before libtinygltf, they take the calls
# of the glTF output (chapter 10) and fail ("FS callback not set"). libassimp.so names libdraco
# itself, so leaving it off the link line still loads it, after libtinygltf.
get_target_property(_stackbook_assimp_links assimp::assimp INTERFACE_LINK_LIBRARIES)
if(_stackbook_assimp_links)
  list(REMOVE_ITEM _stackbook_assimp_links draco::draco)
  set_target_properties(assimp::assimp PROPERTIES INTERFACE_LINK_LIBRARIES "${_stackbook_assimp_links}")
endif()
# Threads (chapter 10): oneTBB's parallel loops, inside the library only.
stackbook_require_package(TBB libtbb-dev)
# The simulator (chapter 10): scene files in JSON, the command line, glTF output.
stackbook_require_package(nlohmann_json nlohmann-json3-dev 3.10)
stackbook_require_package(CLI11 libcli11-dev)
stackbook_require_package(TinyGLTF libtinygltf-dev)
# three.js for the offline 3D viewer page (copied next to the viewer; not a build input).
find_path(STACKBOOK_THREE_DIR three.min.js PATHS /usr/share/javascript/three NO_DEFAULT_PATH)
if(NOT STACKBOOK_THREE_DIR)
  message(FATAL_ERROR "stackbook needs three.js for its 3D viewer page.\n"
                      "On Debian 12 install it with:  apt-get install libjs-three")
endif()
