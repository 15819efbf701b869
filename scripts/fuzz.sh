#!/usr/bin/env bash
# libFuzzer on the input paths (issue 8): the OBJ loader, the image/environment loaders, the
# transport-cache reader and the option parser, each for a bounded time, seeded from the
# fixtures in tests/data. Needs clang (installed from Debian when run as root).
#   bash scripts/fuzz.sh [SECONDS_PER_TARGET] [TARGET...]     (default 60 s, every target)
# Crashes are saved under build-fuzz/artifacts/TARGET/ (turn each into a fixture and a fix);
# the corpora grow in build-fuzz/corpus/TARGET/.
set -euo pipefail
cd "$(dirname "$0")/.."
seconds=${1:-60}
shift || true
targets=("$@")
[ ${#targets[@]} -eq 0 ] && targets=(fuzz_obj fuzz_image fuzz_cache fuzz_args)

if ! command -v clang++ >/dev/null; then
  if [ "$(id -u)" = 0 ]; then apt-get install -y clang; else
    echo "fuzz.sh: clang is missing: sudo apt-get install -y clang" >&2; exit 2; fi
fi
flags="-fsanitize=fuzzer-no-link,address,undefined -fno-sanitize-recover=undefined"
CC=clang CXX=clang++ cmake -S . -B build-fuzz -DCMAKE_BUILD_TYPE=RelWithDebInfo -DPRT_FUZZ=ON \
  -DBUILD_TESTING=OFF "-DCMAKE_CXX_FLAGS=$flags" >/dev/null
cmake --build build-fuzz --parallel "${PRT_JOBS:-$(nproc)}" --target "${targets[@]}"

# Seed corpora from the fixtures.
seed() {  # seed TARGET FILE [PREFIX_BYTE]; the seed is named after the whole path (faces of
  local dir=build-fuzz/corpus/$1 name=${2//\//_}  # different cubemaps share a file name)
  mkdir -p "$dir"
  if [ $# -ge 3 ]; then { printf "\\$(printf %03o "$3")"; cat "$2"; } >"$dir/seed_$name"
  else cp "$2" "$dir/seed_$name"; fi
}
for f in tests/data/obj/*.obj tests/data/obj/*.mtl; do seed fuzz_obj "$f"; done
for f in tests/data/images/*; do
  case "$f" in *.png) b=0 ;; *.jpg) b=1 ;; *.hdr) b=2 ;; *.exr) b=3 ;; *) continue ;; esac
  seed fuzz_image "$f" "$b"
done
for f in tests/data/cubemaps/*/posx.png; do seed fuzz_image "$f" 0; done
for f in tests/data/cache/*; do seed fuzz_cache "$f"; done
if [ -x build/prt ]; then  # a real cache as a seed, when the normal build exists
  tmp=$(mktemp -d)
  build/prt render --mesh tests/data/obj/quad.obj --env furnace --frames 1 --size 8x8 --samples 16 \
    --out "$tmp" --quiet && cp "$tmp/transport.cache" build-fuzz/corpus/fuzz_cache/seed_real.cache
  rm -rf "$tmp"
fi
mkdir -p build-fuzz/corpus/fuzz_args
printf -- '--lmax\n4\n--frames\n3\n--size\n64x32\n' >build-fuzz/corpus/fuzz_args/seed_1
printf -- '--env=sky:sun=3\n--albedo\n0.5,0.5,0.5\n--view\ntransport:3\n--quiet\n' >build-fuzz/corpus/fuzz_args/seed_2
printf -- '--background\n1,2,3\n--axis\n0,0,1\n--ssaa\n4\n--eye\n1,2,3\n--fov\n40\n' >build-fuzz/corpus/fuzz_args/seed_3

status=0
for t in "${targets[@]}"; do
  mkdir -p "build-fuzz/artifacts/$t"
  echo "== $t for ${seconds}s"
  if ! "build-fuzz/fuzz/$t" "build-fuzz/corpus/$t" -max_total_time="$seconds" -timeout=10 \
      -rss_limit_mb=2048 -max_len=65536 -print_final_stats=1 \
      -artifact_prefix="build-fuzz/artifacts/$t/" 2>"build-fuzz/$t.log"; then
    echo "$t: FAILED, see build-fuzz/$t.log and build-fuzz/artifacts/$t/"; status=1
  fi
  grep -E "^#[0-9]+.*(DONE|pulse)|stat::number_of_executed_units|cov:" "build-fuzz/$t.log" | tail -2
done
exit $status
