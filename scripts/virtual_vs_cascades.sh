#!/usr/bin/env bash
# Virtual shadow maps against cascades at equal physical texels (README's "Virtual shadow maps"):
# on the default scene, a grazing sun and an overhead view (far/near 1,000), each method measured at
# one texture of RESOLUTION² (the virtual map's physical pool, the cascades' atlas) and followed along
# a sideways camera path. Prints a Markdown table. Needs a build (scripts/build.sh) and an X display
# (xvfb-run -a) for shimmer's plot. Usage: scripts/virtual_vs_cascades.sh [RESOLUTION] [FRAMES]
set -euo pipefail
cd "$(dirname "$(readlink -f "$0")")/.."
resolution=${1:-2048}
frames=${2:-30}
cli=build/app/shadowlab
out=$(mktemp -d)
trap 'rm -rf "$out"' EXIT
echo "| scene | method | misclassified | m_perspective p95 | max | pages resident / marked | texels drawn per frame: fresh | with a page cache | verdicts flipped |"
echo "|---|---|---|---|---|---|---|---|---|"
for scene in default grazing_sun overhead_view; do
  for method in "virtual" "cascades" "cascades --set stabilize=on"; do
    # shellcheck disable=SC2086  # the method's word and its settings
    "$cli" measure "data/scenes/$scene.json" --method $method -r "$resolution" --size 640x360 --json \
      2>/dev/null >"$out/measure.json"
    # shellcheck disable=SC2086
    "$cli" shimmer "data/scenes/$scene.json" --method $method -r "$resolution" --size 640x360 \
      --frames "$frames" --out "$out/shimmer" >"$out/shimmer.txt" 2>/dev/null
    python3 - "$scene" "$method" "$out" <<'PY'
import csv, json, sys
scene, method, out = sys.argv[1:]
m = json.load(open(out + "/measure.json"))
rows = list(csv.DictReader(open(out + "/shimmer/shimmer.csv")))
later = rows[1:]
fresh = sum(float(r["texels_fresh"]) for r in later) / len(later)
cached = sum(float(r["texels_cached"]) for r in later) / len(later)
flips = sum(int(r["flips"]) for r in rows)
transitions = sum(int(r["transitions"]) for r in rows)
pages = m.get("pages")
resident = "%d / %d" % (pages["resident"], pages["marked"]) if pages else "—"
print("| %s | %s | %.4f %% | %.2f | %.2f | %s | %.0f | %.0f | %d of %d |" % (
    scene, method.replace("--set ", ""), 100 * m["misclassified"], m["m_perspective"]["p95"],
    m["m_perspective"]["max"], resident, fresh, cached, flips, transitions))
PY
  done
done
