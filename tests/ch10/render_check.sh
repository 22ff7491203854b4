#!/bin/sh
# Chapter 10: check that the outputs open in a browser. Writes the sample outputs (a few
# falling boxes: an animated SVG in 2D, a .glb and its three.js viewer page in 3D) with
# test_ch10, screenshots them in headless Chromium and checks that each picture shows
# more than a blank page.
#
#   tests/ch10/render_check.sh BUILD_DIR [SHOT_DIR]
#
# BUILD_DIR is a configured and built stackbook build folder (test_ch10 is built there);
# SHOT_DIR defaults to /tmp/stackbook_shots. Exit status 0: both pictures show bodies;
# 77 (CTest's SKIP_RETURN_CODE convention): Chromium or python3 is missing; 1: a check failed.
set -eu

build=${1:?usage: render_check.sh BUILD_DIR [SHOT_DIR]}
shots=${2:-/tmp/stackbook_shots}

chrome=""
for candidate in chromium chromium-browser google-chrome; do
  if command -v "$candidate" >/dev/null 2>&1; then chrome=$candidate; break; fi
done
if [ -z "$chrome" ]; then
  echo "render_check: SKIPPED: no chromium found (apt-get install chromium)"
  exit 77
fi
if ! command -v python3 >/dev/null 2>&1; then
  echo "render_check: SKIPPED: python3 is needed to inspect the screenshots"
  exit 77
fi
tests=$(find "$build" -name test_ch10 -type f -perm -u+x | head -n 1)
if [ -z "$tests" ]; then
  echo "render_check: no test_ch10 under '$build': build it first (cmake --build $build --target test_ch10)"
  exit 1
fi

mkdir -p "$shots/samples"
shots=$(cd "$shots" && pwd)
STACKBOOK_SAMPLES_DIR="$shots/samples" "$tests" -ts=ch10 -tc="The sample outputs*" >/dev/null

profile=$(mktemp -d)
trap 'rm -rf "$profile"' EXIT
shoot() {  # page, picture, virtual milliseconds
  timeout 120 "$chrome" --headless --no-sandbox --disable-gpu --enable-unsafe-swiftshader \
    --disable-background-networking --disable-component-update --disable-sync --no-first-run \
    --user-data-dir="$profile" --virtual-time-budget="$3" --window-size=1200,900 \
    --screenshot="$2" "file://$1" >/dev/null 2>&1 || true
  if [ ! -s "$2" ]; then echo "render_check: FAILED: no screenshot of $1"; exit 1; fi
}
shoot "$shots/samples/falling_2d.svg" "$shots/falling_2d_svg.png" 1000
shoot "$shots/samples/falling_3d.html" "$shots/falling_3d_viewer.png" 8000

# A picture shows bodies when it has enough pixels in the bodies' saturated colours (the
# samples' boxes are blue, their balls and ring orange); background, ground, grid and text
# are grey. PNG decoding with the standard library only (zlib, 8-bit RGB or RGBA).
python3 - "$shots/falling_2d_svg.png" "$shots/falling_3d_viewer.png" <<'PY'
import struct, sys, zlib

def pixels(path):
    data = open(path, 'rb').read()
    assert data[:8] == b'\x89PNG\r\n\x1a\n', path + ': not a PNG'
    at, idat, width, height, kind = 8, b'', 0, 0, 0
    while at < len(data):
        length, tag = struct.unpack('>I4s', data[at:at + 8])
        body = data[at + 8:at + 8 + length]
        if tag == b'IHDR':
            width, height, depth, kind = struct.unpack('>IIBB', body[:10])
            assert depth == 8 and kind in (2, 6), path + ': unsupported PNG format'
        elif tag == b'IDAT':
            idat += body
        at += 12 + length
    channels = 3 if kind == 2 else 4
    raw, stride = zlib.decompress(idat), width * channels
    rows, previous = [], bytearray(stride)
    for y in range(height):
        filt, line = raw[y * (stride + 1)], bytearray(raw[y * (stride + 1) + 1:(y + 1) * (stride + 1)])
        for x in range(stride):
            a = line[x - channels] if x >= channels else 0
            b, c = previous[x], previous[x - channels] if x >= channels else 0
            if filt == 1: line[x] = (line[x] + a) & 255
            elif filt == 2: line[x] = (line[x] + b) & 255
            elif filt == 3: line[x] = (line[x] + (a + b) // 2) & 255
            elif filt == 4:
                p = a + b - c
                pa, pb, pc = abs(p - a), abs(p - b), abs(p - c)
                line[x] = (line[x] + (a if pa <= pb and pa <= pc else b if pb <= pc else c)) & 255
        rows.append(line)
        previous = line
    return width, height, channels, rows

failed = False
for path in sys.argv[1:]:
    width, height, channels, rows = pixels(path)
    coloured = 0
    for line in rows:
        for x in range(0, width * channels, channels):
            r, g, b = line[x], line[x + 1], line[x + 2]
            if max(r, g, b) - min(r, g, b) > 60:
                coloured += 1
    share = coloured / float(width * height)
    verdict = 'ok' if share > 0.002 else 'FAILED (blank?)'
    print('render_check: %s: %.2f%% of pixels in body colours: %s' % (path, 100 * share, verdict))
    failed = failed or share <= 0.002
sys.exit(1 if failed else 0)
PY
