#!/usr/bin/env bash
# Regenerates the images in docs/images/ that the README shows, with the program itself.
# Usage: bash scripts/make-doc-images.sh [path/to/prt]   (default build/prt)
set -euo pipefail
cd "$(dirname "$0")/.."
prt=${1:-build/prt}
out=docs/images
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
mkdir -p "$out"

"$prt" demo --frames 120 --out "$tmp/demo" --quiet
cp "$tmp/demo/frame_0000.png" "$out/demo.png"
cp "$tmp/demo/frame_0040.png" "$out/demo_turned.png"
"$prt" basis --lmax 3 --cell 64 --out "$out/basis.png" --quiet
# The same scene and transport as the demo (its cache is reused), other views of it.
for v in light:view_light.png irradiance:view_irradiance.png transport:0:view_transport0.png transport:6:view_transport6.png; do
  "$prt" demo --frames 1 --size 400x300 --out "$tmp/demo" --quiet --view "${v%:*}"
  cp "$tmp/demo/frame_0000.png" "$out/${v##*:}"
done
echo "wrote $(ls "$out" | wc -l) images to $out"
