#!/usr/bin/env bash
# Opens every model of the real-model corpus (tests/corpus: Assimp's test models and three OpenArena
# levels) as the corpus test does, and counts what loaded and what was refused, by reason: the table
# in README's "Opening your own models". Needs a build (scripts/build.sh).
set -euo pipefail
cd "$(dirname "$(readlink -f "$0")")/.."
build/tests/shadowlab_corpus_tests --gtest_brief=1 | awk -F'\t' '
  $1 != "corpus" { next }
  $2 == "loaded" { loaded++; next }
  {
    refused++
    reason = $4
    sub(/^cannot read mesh file [^:]*: /, "", reason)   # the path, then Assimp'"'"'s or our reason
    sub(/^mesh file [^:]*: /, "", reason)
    gsub(/"[^"]*"/, "\"…\"", reason); gsub(/[0-9]+/, "N", reason)
    if (length(reason) > 90) reason = substr(reason, 1, 87) "..."
    reasons[reason]++
  }
  END {
    printf "%d files: %d loaded, %d refused\n", loaded + refused, loaded, refused
    for (r in reasons) printf "%5d  %s\n", reasons[r], r | "sort -rn"
  }'
