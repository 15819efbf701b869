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
cp "$tmp/demo/frame_0040.png" "$out/demo_turned.png"
# The README's animation: a full turn as an animated PNG, small enough to load quickly.
"$prt" demo --frames 60 --size 320x240 --fps 20 --out "$tmp/turning" --video "$out/demo_turning.png" --quiet
"$prt" basis --lmax 3 --cell 64 --out "$out/basis.png" --quiet
# The same scene and transport as the demo (its cache is reused), other views of it.
for v in light:view_light.png irradiance:view_irradiance.png transport:0:view_transport0.png transport:6:view_transport6.png; do
  "$prt" demo --frames 1 --size 400x300 --out "$tmp/demo" --quiet --view "${v%:*}"
  cp "$tmp/demo/frame_0000.png" "$out/${v##*:}"
done
# Glossy transfer: a highlight sliding as the camera orbits (transfer matrices), then the lobe
# term alone (--view glossy, with the raw light: the ringing is what they show) for a few
# exponents N and band limits lmax.
glossy="--material phong:100,0.5 --albedo 0.3,0.3,0.3 --exposure 0 --size 320x240"
# (the full matrices: these pictures predate the clustered-PCA default and show what it approximates)
"$prt" render $glossy --lmax 10 --orbit 60 --turns 0 --frames 3 --cpca off --out "$tmp/orbit" --quiet
for i in 0 1 2; do cp "$tmp/orbit/frame_000$i.png" "$out/glossy_orbit_$i.png"; done
for lmax in 2 6 12; do
  "$prt" render $glossy --lmax $lmax --view glossy --window none --frames 1 --out "$tmp/lmax$lmax" --quiet
  cp "$tmp/lmax$lmax/frame_0000.png" "$out/glossy_n100_lmax$lmax.png"
done
for n in 10 1000; do
  "$prt" render ${glossy/phong:100/phong:$n} --lmax 12 --view glossy --window none --frames 1 --out "$tmp/n$n" --quiet
  cp "$tmp/n$n/frame_0000.png" "$out/glossy_n${n}_lmax12.png"
done
echo "wrote $(ls "$out" | wc -l) images to $out"
# All-frequency shadows: the demo's sun shadow at SH lmax 2, 4 and 16 and with wavelets (the same
# exposure), then the light the wavelets keep with 16, 64 and 256 terms (--view light), looking
# at the sun (elevation 40, azimuth 35: direction 0.44,0.64,-0.63) from beside the knot.
sun="--transport shadowed --exposure -1.6 --size 320x240 --frames 1"
for lmax in 2 4 16; do
  "$prt" demo $sun --lmax $lmax --out "$tmp/sun_sh$lmax" --quiet
  cp "$tmp/sun_sh$lmax/frame_0000.png" "$out/sun_sh_lmax$lmax.png"
done
"$prt" demo $sun --basis wavelet --out "$tmp/sun_wavelet" --quiet
cp "$tmp/sun_wavelet/frame_0000.png" "$out/sun_wavelet.png"
for k in 16 64 256; do
  "$prt" demo --transport unshadowed --basis wavelet --view light --light-terms $k --exposure -3 --size 320x240 \
    --eye 6,0.5,6 --target 10.39,6.93,-0.27 --fov 60 --frames 1 --out "$tmp/light$k" --quiet
  cp "$tmp/light$k/frame_0000.png" "$out/wavelet_light_$k.png"
done
