#pragma once
/// \file
/// \brief One offline HTML page that plays an animated .glb with three.js (chapter 10).

#include <string>

namespace stackbook {

// [viewer_options]
/// Where writeViewerHtml finds three.js, and what the page is called.
struct ViewerOptions {
  /// Folder holding three.min.js, examples/js/loaders/GLTFLoader.js and
  /// examples/js/controls/OrbitControls.js (the classic, non-module scripts of three.js
  /// r111, Debian's libjs-three). Empty: the folder found when stackbook was configured.
  std::string threeDir;
  /// The page title; empty: the .glb's file name.
  std::string title;
};
// [viewer_options]

// [write_viewer_html]
/// Write `htmlPath`: a single self-contained page that plays the animation in `glbPath`
/// in any browser, offline, opened straight from disk. The page inlines three.js, its
/// GLTFLoader and OrbitControls, and the .glb itself as base64 (a page opened from file://
/// may not fetch other files), which it decodes and hands to GLTFLoader.parse. An
/// AnimationMixer loops the first animation; the camera is fitted to the bodies' motion;
/// the page has a ground grid under the lowest point of the motion, hemisphere and
/// directional lights, orbit controls (drag, scroll), a play/pause button (or space), a
/// time slider and the simulated time.
///
/// Throws std::runtime_error naming the file when the .glb or a three.js script cannot be
/// read, or `htmlPath` cannot be written.
void writeViewerHtml(const std::string& glbPath, const std::string& htmlPath,
                     const ViewerOptions& options = {});
// [write_viewer_html]

}  // namespace stackbook
