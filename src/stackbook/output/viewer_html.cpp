#include "stackbook/output/viewer_html.hpp"

#include <stdexcept>

#include "stackbook/output/output_files.hpp"

#ifndef STACKBOOK_THREE_DIR
#define STACKBOOK_THREE_DIR "/usr/share/javascript/three"
#endif

namespace stackbook {

namespace {

// Inline script text must not close its <script> element early: "</script" inside a
// string or a comment is written "<\/script", which JavaScript reads the same.
std::string scriptSafe(std::string text) {
  std::size_t at = 0;
  while ((at = text.find("</script", at)) != std::string::npos) {
    text.replace(at, 2, "<\\/");
    at += 3;
  }
  return text;
}

std::string htmlEscape(const std::string& text) {
  std::string out;
  for (char c : text) {
    if (c == '&') out += "&amp;";
    else if (c == '<') out += "&lt;";
    else if (c == '>') out += "&gt;";
    else out += c;
  }
  return out;
}

std::string baseName(const std::string& path) {
  const std::size_t slash = path.find_last_of('/');
  return slash == std::string::npos ? path : path.substr(slash + 1);
}

// The page's own code: decode the .glb, build the scene, fit the camera to the motion,
// play the clip in a loop. Plain ES5-style script for three.js r111's global THREE.
constexpr const char* kViewerScript = R"JS(
(function () {
  'use strict';
  var status = document.getElementById('status');
  function fail(message) { status.textContent = message; status.style.display = 'block'; }
  if (typeof THREE === 'undefined' || !THREE.GLTFLoader || !THREE.OrbitControls) {
    fail('three.js, GLTFLoader or OrbitControls did not load.');
    return;
  }
  var text = document.getElementById('glb').textContent.replace(/\s+/g, '');
  var raw = atob(text);
  var bytes = new Uint8Array(raw.length);
  for (var i = 0; i < raw.length; ++i) bytes[i] = raw.charCodeAt(i);

  var renderer = new THREE.WebGLRenderer({ antialias: true, preserveDrawingBuffer: true });
  renderer.setPixelRatio(window.devicePixelRatio);
  renderer.setSize(window.innerWidth, window.innerHeight);
  renderer.gammaOutput = true;
  renderer.gammaFactor = 2.2;
  document.body.appendChild(renderer.domElement);

  var scene = new THREE.Scene();
  scene.background = new THREE.Color(0xeef0f3);
  var camera = new THREE.PerspectiveCamera(40, window.innerWidth / window.innerHeight, 0.01, 1000);
  camera.position.set(4, 3, 6);
  scene.add(new THREE.HemisphereLight(0xffffff, 0x707080, 0.75));
  var sun = new THREE.DirectionalLight(0xffffff, 0.75);
  scene.add(sun);
  var controls = new THREE.OrbitControls(camera, renderer.domElement);

  var mixer = null, action = null, duration = 0, playing = true;
  var clock = new THREE.Clock();
  var playButton = document.getElementById('play');
  var slider = document.getElementById('seek');
  var timeLabel = document.getElementById('time');
  function setPlaying(on) { playing = on; playButton.textContent = on ? 'Pause' : 'Play'; }
  playButton.addEventListener('click', function () { setPlaying(!playing); });
  window.addEventListener('keydown', function (e) {
    if (e.code === 'Space') { setPlaying(!playing); e.preventDefault(); }
  });
  slider.addEventListener('input', function () {
    if (mixer) { setPlaying(false); mixer.setTime(parseFloat(slider.value) * duration); }
  });

  new THREE.GLTFLoader().parse(bytes.buffer, '', function (gltf) {
    var root = gltf.scene;
    scene.add(root);
    // The motion's bounding box: the scene sampled at 33 times across the clip.
    var box = new THREE.Box3();
    if (gltf.animations.length > 0) {
      mixer = new THREE.AnimationMixer(root);
      action = mixer.clipAction(gltf.animations[0]);
      action.play();
      duration = gltf.animations[0].duration;
      for (var k = 0; k <= 32; ++k) {
        mixer.setTime(duration * k / 32);
        root.updateMatrixWorld(true);
        box.expandByObject(root);
      }
      mixer.setTime(0);
    } else {
      root.updateMatrixWorld(true);
      box.expandByObject(root);
    }
    if (box.isEmpty()) box.set(new THREE.Vector3(-1, -1, -1), new THREE.Vector3(1, 1, 1));
    var center = box.getCenter(new THREE.Vector3());
    var size = box.getSize(new THREE.Vector3());
    var radius = Math.max(0.5 * size.length(), 1e-3);
    var span = Math.pow(10, Math.ceil(Math.log10(2.5 * Math.max(size.x, size.z, radius))));
    var grid = new THREE.GridHelper(span, 20, 0x8890a0, 0xc4c8d0);
    grid.position.set(center.x, box.min.y - 1e-3 * radius, center.z);
    scene.add(grid);
    var distance = 1.15 * radius / Math.sin(THREE.MathUtils ? THREE.MathUtils.degToRad(20) : 20 * Math.PI / 180);
    camera.position.copy(center).add(new THREE.Vector3(0.55, 0.45, 0.7).normalize().multiplyScalar(distance));
    camera.near = distance / 100;
    camera.far = distance * 100;
    camera.updateProjectionMatrix();
    controls.target.copy(center);
    controls.update();
    sun.position.copy(center).add(new THREE.Vector3(0.5, 1.0, 0.35).multiplyScalar(3 * radius));
    sun.target.position.copy(center);
    scene.add(sun.target);
    document.body.setAttribute('data-loaded', 'true');
  }, function (error) {
    fail('Could not read the embedded glTF: ' + (error && error.message ? error.message : error));
  });

  window.addEventListener('resize', function () {
    camera.aspect = window.innerWidth / window.innerHeight;
    camera.updateProjectionMatrix();
    renderer.setSize(window.innerWidth, window.innerHeight);
  });
  function frame() {
    requestAnimationFrame(frame);
    var dt = clock.getDelta();
    if (mixer) {
      if (playing) mixer.update(dt);
      var t = duration > 0 ? action.time % duration : 0;
      timeLabel.textContent = 't = ' + t.toFixed(2) + ' s / ' + duration.toFixed(2) + ' s';
      if (playing && duration > 0) slider.value = t / duration;
    }
    controls.update();
    renderer.render(scene, camera);
  }
  frame();
})();
)JS";

}  // namespace

void writeViewerHtml(const std::string& glbPath, const std::string& htmlPath, const ViewerOptions& options) {
  using output_detail::readFileOrThrow;
  const std::string threeDir = options.threeDir.empty() ? std::string(STACKBOOK_THREE_DIR) : options.threeDir;
  const std::string glb = readFileOrThrow("writeViewerHtml", glbPath);
  const std::string three = readFileOrThrow("writeViewerHtml (three.js)", threeDir + "/three.min.js");
  const std::string loader =
      readFileOrThrow("writeViewerHtml (three.js)", threeDir + "/examples/js/loaders/GLTFLoader.js");
  const std::string controls =
      readFileOrThrow("writeViewerHtml (three.js)", threeDir + "/examples/js/controls/OrbitControls.js");
  const std::string title = htmlEscape(options.title.empty() ? baseName(glbPath) : options.title);

  std::string html;
  html.reserve(three.size() + loader.size() + controls.size() + glb.size() * 4 / 3 + 8192);
  html += "<!DOCTYPE html>\n<html lang=\"en\">\n<head>\n<meta charset=\"utf-8\">\n";
  html += "<meta name=\"viewport\" content=\"width=device-width, initial-scale=1\">\n";
  html += "<title>" + title + " - stackbook viewer</title>\n";
  html += "<style>\n"
          "html, body { margin: 0; height: 100%; overflow: hidden; background: #eef0f3; }\n"
          "body { font: 14px sans-serif; color: #222; }\n"
          "canvas { display: block; }\n"
          "#bar { position: absolute; left: 12px; right: 12px; bottom: 12px; display: flex; gap: 10px;\n"
          "       align-items: center; background: rgba(255,255,255,0.85); padding: 6px 10px; border-radius: 6px; }\n"
          "#seek { flex: 1; }\n"
          "#time { font-variant-numeric: tabular-nums; min-width: 12em; }\n"
          "#title { position: absolute; left: 12px; top: 10px; }\n"
          "#status { display: none; position: absolute; left: 12px; top: 36px; color: #a00; }\n"
          "</style>\n</head>\n<body>\n";
  html += "<div id=\"title\">" + title + " &middot; drag to orbit, scroll to zoom, space to pause</div>\n";
  html += "<div id=\"status\"></div>\n";
  html += "<div id=\"bar\"><button id=\"play\">Pause</button>"
          "<input id=\"seek\" type=\"range\" min=\"0\" max=\"1\" step=\"0.001\" value=\"0\">"
          "<span id=\"time\">t = 0.00 s</span></div>\n";
  html += "<script>\n" + scriptSafe(three) + "\n</script>\n";
  html += "<script>\n" + scriptSafe(loader) + "\n</script>\n";
  html += "<script>\n" + scriptSafe(controls) + "\n</script>\n";
  html += "<script id=\"glb\" type=\"application/octet-stream\">\n";
  const std::string encoded = output_detail::base64Encode(glb);
  for (std::size_t at = 0; at < encoded.size(); at += 120) html += encoded.substr(at, 120) + '\n';
  html += "</script>\n<script>" + std::string(kViewerScript) + "</script>\n</body>\n</html>\n";
  output_detail::writeFileOrThrow("writeViewerHtml", htmlPath, html);
}

}  // namespace stackbook
