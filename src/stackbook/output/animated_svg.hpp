#pragma once
/// \file
/// \brief A 2D recording as a self-contained animated SVG that plays in any browser
/// (chapter 10).

#include <string>

#include "stackbook/output/recording.hpp"

namespace stackbook {

// [svg_options]
/// How writeAnimatedSvg draws and times the animation.
struct SvgOptions {
  /// At most this many frames are written (evenly spaced, first and last always kept);
  /// a 10 s run recorded at 60 fps plays smoothly from 300. At least 2.
  int maxFrames = 300;
  /// Wall-clock seconds per simulated second (2 plays at half speed).
  double playbackSlowdown = 1.0;
  /// Width of the drawing in CSS pixels, the height following the motion's aspect ratio;
  /// 0 fills the browser window (width and height 100%), the motion centred and whole.
  double widthPixels = 0.0;
  /// Blank border around the motion's bounding box, as a fraction of its larger side.
  double margin = 0.05;
  /// Outline width as a fraction of the bounding box's larger side.
  double strokeFraction = 0.002;
  /// Show the simulated time (to 0.1 s, or coarser for long runs) and a progress bar.
  bool showTime = true;
  /// Background colour (any CSS colour).
  std::string background = "#ffffff";
  /// Draw, at each written frame, the contacts of the step that reached it
  /// (Recording::contacts()): a dot at each point and a line along its normal.
  bool drawContacts = false;
  /// Length of a drawn normal as a fraction of the bounding box's larger side.
  double contactNormalFraction = 0.03;
  /// Colour of the contact dots and normals (any CSS colour).
  std::string contactColor = "#d62728";
};
// [svg_options]

// [write_animated_svg]
/// Write `recording` to `path` as an animated SVG: y points up (the drawing is flipped),
/// the view box holds every vertex of every body at every recorded frame, a static body
/// is drawn once, and each dynamic body is a group whose translation and rotation are
/// SMIL animateTransform elements (calcMode linear, keyTimes at the recorded times) that
/// loop forever. Each body's outline is its BodyVisual mesh: the segments are chained into
/// closed loops, all drawn as one path with fill-rule evenodd, so an annulus shows its
/// hole. Rotation angles are unwrapped between frames so that linear interpolation turns
/// the short way. With options.drawContacts, each written frame whose step applied
/// impulses gets a group of dots (the points) and lines (the normals), visible from that
/// frame to the next (SMIL discrete visibility).
///
/// Throws std::invalid_argument if the recording has no frame or a visual's segments
/// refer to missing vertices, std::runtime_error naming `path` if it cannot be written.
void writeAnimatedSvg(const Recording<2>& recording, const std::string& path,
                      const SvgOptions& options = {});
// [write_animated_svg]

}  // namespace stackbook
