#!/bin/sh
# replay.sh FUZZER DIR: runs every file of DIR/FAMILY/ once through FUZZER as FAMILY.
set -e
fuzzer=$1
dir=$2
n=0
for fam in "$dir"/*/; do
  family=$(basename "$fam")
  set -- "$fam"*
  [ -e "$1" ] || continue
  TMOP_FUZZ_FAMILY=$family "$fuzzer" -rss_limit_mb=2048 -timeout=10 "$@"
  n=$((n + $#))
done
echo "replayed $n regression inputs"
[ "$n" -gt 0 ]
