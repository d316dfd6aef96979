#!/bin/bash
# Dumps and summaries of every built-in scene and every file of scenes/, each in the course, stable and auto
# solvers, 200 frames headless, into OUTDIR (timings left out): for a refactor that must keep every result bit
# for bit, run it with the build before and the build after and compare with `diff -r BEFORE AFTER`.
#   tools/compare_dumps.sh GAME_BINARY OUTDIR
set -u
if [ $# -ne 2 ] || [ ! -x "$1" ]; then
  echo "usage: tools/compare_dumps.sh GAME_BINARY OUTDIR (GAME_BINARY: a build/game)" >&2
  exit 2
fi
bin=$1 out=$2
root=$(cd "$(dirname "$0")/.." && pwd)
mkdir -p "$out"
for s in walls drift impulse bounce many cradle gas stack "$root"/scenes/*.json; do
  for m in course stable auto; do
    n=$(basename "$s" .json)-$m
    "$bin" --scene "$s" --headless --frames 200 --solver $m --dump "$out/$n.csv" > "$out/$n.out" 2>&1
    echo "rc=$?" >> "$out/$n.out"
    sed -i '/ms\/step\|ms per\| ms\b\|time/d' "$out/$n.out"
  done
done
echo "compare_dumps: $(ls "$out" | wc -l) files in $out"
