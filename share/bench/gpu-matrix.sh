#!/usr/bin/env bash
# The benchmark matrix on a GPU machine, headless through an EGL device, from the portable
# package (docs/portable-package.md) or any install:
#   gpu-matrix.sh <osgGlyphs folder with bin/> <output folder> [EGL device index, default 0]
# Writes sparse.csv/.png (the default radius, a constant covered fraction of the view) and
# dense.csv/.png (radius 0.4 x the mean spacing), 1e3 to 1e8 glyphs at 1920x1080, every
# technique, spheres and cones, and renderer.txt naming the card, the driver and the EGL device.
# A case slower than 2 s a frame ends its technique's larger sizes. GPU_MATRIX_N overrides the sizes.
set -euo pipefail
package=${1:?usage: gpu-matrix.sh <osgGlyphs folder> <output folder> [device]}
out=${2:?usage: gpu-matrix.sh <osgGlyphs folder> <output folder> [device]}
mkdir -p "$out"
export OSGGLYPHS_HEADLESS=egl OSGGLYPHS_EGL_DEVICE=${3:-0}

"$package/bin/osgglyphviewer" --output "$out/default-scene.png" --size 1920 1080 | tee "$out/renderer.txt"
grep -q "OpenGL through EGL device" "$out/renderer.txt" || { echo "gpu-matrix: no EGL device was used" >&2; exit 1; }

matrix=(--n "${GPU_MATRIX_N:-1000,10000,100000,1000000,10000000,100000000}" --shapes sphere,cone --size 1920 1080
        --frames 20 --max-ms 2000)
"$package/bin/osgglyphbench" "${matrix[@]}" --csv "$out/sparse.csv" --plot "$out/sparse.png"
"$package/bin/osgglyphbench" "${matrix[@]}" --radius-spacing 0.4 --csv "$out/dense.csv" --plot "$out/dense.png"
echo "gpu-matrix: wrote $out/{sparse,dense}.{csv,png} and renderer.txt"
