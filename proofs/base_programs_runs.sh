#!/usr/bin/env bash
# Regenerates proofs/designs/base_programs.csv, the base cases of proofs/attainment_unions.md: the
# sweep's best program (seed 1, default starts, as in experiments/docs/attainment.md) for D at N = 12
# and 16..31, A and E at 12..23, S at 12 and 14..27, and the closed-form D3 design for D at N = 14
# (the sweep's 14-point designs are degenerate for the certificate). proof.attainment_unions certifies
# every row; this script only makes the file. From the repository root after scripts/build.sh.
set -euo pipefail
scalcal="${SCALCAL:-build/experiments/scalcal}"
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
"$scalcal" sweep --positions 12..31 --criteria D,A,E,S --seed 1 --out "$work/sweep.csv" >/dev/null
/usr/bin/python3 - "$work/sweep.csv" proofs/designs/d3_14.csv > proofs/designs/base_programs.csv <<'PY'
import csv, sys
wanted = {"D": [12] + list(range(16, 32)), "A": list(range(12, 24)), "E": list(range(12, 24)),
          "S": [12] + list(range(14, 28))}
rows = {(r["criterion"], int(r["positions"])): r["program"] for r in csv.DictReader(open(sys.argv[1]))}
d3 = list(csv.reader(open(sys.argv[2])))[1:]
rows[("D", 14)] = ";".join(" ".join(p) for p in d3)
wanted["D"].insert(1, 14)
print("criterion,positions,program")
for c, ns in wanted.items():
    for n in ns:
        print(f'{c},{n},"{rows[(c, n)]}"')
PY
