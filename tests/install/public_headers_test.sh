#!/usr/bin/env bash
# Compiles a translation unit that includes tmop/tmop.h with only tmop's source dir and Eigen on
# the include path, and fails if any Ceres, glog or gflags header is reached (they sit in
# /usr/include on Debian, so the include path alone would not catch a leak).
set -euo pipefail
cxx=$1 src=$2 eigen=$3
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
printf '#include "tmop/tmop.h"\nint main() { tmop::Mesh mesh; return mesh.num_vertices(); }\n' \
  >"$tmp/consumer.cc"
"$cxx" -std=c++17 -fsyntax-only -H -I"$src" -I"$eigen" "$tmp/consumer.cc" 2>"$tmp/headers"
if grep -E '/(ceres|glog|gflags)/' "$tmp/headers"; then
  echo "tmop/tmop.h reaches the headers above: public headers must not expose Ceres/glog/gflags"
  exit 1
fi
echo "tmop/tmop.h compiles without Ceres, glog or gflags"
