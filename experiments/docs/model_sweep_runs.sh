#!/bin/sh
# Re-makes the per-model attainment table of sweep.md: sh experiments/docs/model_sweep_runs.sh BUILD_DIR
# (prints Markdown; needs python3 for the JSON). For each model other than the paper's and each
# criterion, `sweep --model M --positions P..40` (P the model's parameters, default starts, seed 1)
# and the N whose best program is within a relative 1e-8 of the model's proven limit.
set -e
S=${1:-build}/experiments/scalcal

summary_row() { python3 -c '
import json, sys
rows = json.load(sys.stdin)
model, crit = sys.argv[1], sys.argv[2]
hit = [r["positions"] for r in rows if r["ratio"] - 1 <= 1e-8]
miss = [r for r in rows if r["ratio"] - 1 > 1e-8]
def ranges(ns):
    out, i = [], 0
    while i < len(ns):
        j = i
        while j + 1 < len(ns) and ns[j + 1] == ns[j] + 1: j += 1
        out.append(str(ns[i]) if i == j else "%d-%d" % (ns[i], ns[j]))
        i = j + 1
    return ", ".join(out) if out else "none"
worst = max(miss, key=lambda r: r["ratio"]) if miss else None
best_miss = min(miss, key=lambda r: r["ratio"]) if miss else None
print("| %s | %s | %.10g | %s | %s | %s |" % (model, crit, rows[0]["limit"], ranges(hit),
      "%.6g (N = %d)" % (best_miss["ratio"], best_miss["positions"]) if miss else "-",
      "%.6g (N = %d)" % (worst["ratio"], worst["positions"]) if miss else "-"))
' "$1" "$2"; }

echo "| model | criterion | limit | N within 1e-8 of the limit | closest miss (ratio) | worst (ratio) |"
echo "| --- | --- | --- | --- | --- | --- |"
for m in bias3 axis6 cubic12; do
  case $m in bias3) P=3 ;; axis6) P=6 ;; cubic12) P=12 ;; esac
  for c in D A E S; do
    "$S" sweep --model $m --positions $P..40 --criteria $c --json --no-timing | summary_row $m $c
  done
done
