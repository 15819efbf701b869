#!/usr/bin/env bash
# Installs the Debian packages prt needs to build (and, with `test`, to test), and nothing that
# is already there.
# Idempotent: a machine that has everything runs no apt command at all.
set -euo pipefail

packages=(g++ cmake make ninja-build pkg-config
          zlib1g-dev libglm-dev libstb-dev libtinyobjloader-dev libnanoflann-dev doctest-dev libopenexr-dev
          libcpp-httplib-dev nlohmann-json3-dev)
# `bash scripts/install-deps.sh test`: also what the tests run besides prt. The --video tests
# encode .mp4 and .webm and decode every video with Debian's ffmpeg (prt itself needs it only for
# those two formats, and says so when it is missing). The report tests render the Markdown tables
# prt writes with Debian's cmark-gfm, GitHub's own Markdown renderer, to check every row keeps its
# columns (prt itself never runs it). The tests of `prt view` drive Debian's chromium, headless,
# from python3 over the DevTools Protocol (scripts/cdp.py), to check the page in a real browser.
# The slurm tier runs prt farm against a real Slurm of one node: Debian's slurm-wlm (slurmctld,
# slurmd, sbatch) and munge, which its test starts and stops itself.
[ "${1:-}" = test ] && packages+=(ffmpeg cmark-gfm chromium python3 slurm-wlm munge)
[ -n "${PRT_EXTRA_PACKAGES:-}" ] && read -r -a extra <<<"$PRT_EXTRA_PACKAGES" && packages+=("${extra[@]}")

missing=()
for p in "${packages[@]}"; do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
done
[ ${#missing[@]} -eq 0 ] && exit 0

if [ "$(id -u)" -ne 0 ]; then
  echo "prt: missing packages: ${missing[*]}" >&2
  echo "prt: run: sudo apt-get update && sudo apt-get install -y ${missing[*]}" >&2
  exit 1
fi
echo "prt: installing ${missing[*]}" >&2
export DEBIAN_FRONTEND=noninteractive
apt-get update -qq
apt-get install -y -qq --no-install-recommends "${missing[@]}" >/dev/null
