#!/usr/bin/env bash
# Regenerates experiments/docs/attainment.md: the sweep's best program for every N and criterion
# (seed 1, default starts), each run through `scalcal certify`. Usage:
#   attainment_runs.sh [A..B] [CRITERIA]      (default 9..40 D,A,E,S)
# from the repository root after scripts/build.sh; writes the table to stdout.
set -euo pipefail
range="${1:-9..40}"
criteria="${2:-D,A,E,S}"
scalcal="${SCALCAL:-build/experiments/scalcal}"
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
"$scalcal" sweep --positions "$range" --criteria "$criteria" --seed 1 --out "$work/sweep.csv" >/dev/null
python3 - "$work" "$scalcal" <<'PY'
import csv, json, subprocess, sys
work, scalcal = sys.argv[1], sys.argv[2]
rows = list(csv.DictReader(open(f"{work}/sweep.csv")))
print("| crit | N | best value | status | radius / enclosure | certify s | sweep s |")
print("| --- | --- | --- | --- | --- | --- | --- |")
for r in rows:
    path = f"{work}/{r['criterion']}{r['positions']}.csv"
    with open(path, "w") as f:
        f.write("x,y,z\n")
        for p in r["program"].split(";"):
            f.write(",".join(p.split()) + "\n")
    out = subprocess.run([scalcal, "certify", path, "--criterion", r["criterion"], "--json"],
                         check=True, capture_output=True, text=True).stdout
    j = json.loads(out)
    if j["enclosure"]:
        lo, hi = j["enclosure"]
        shown = f"[{lo[:36]}..., {hi[:36]}...] ({j['enclosure_digits']} digits)"
    elif j["radius"]:
        shown = f"radius {j['radius']}"
    else:
        shown = j["reason"]
    print(f"| {r['criterion']} | {r['positions']} | {float(r['value']):.10g} | {j['status']} | {shown} | "
          f"{j['seconds']:.3f} | {float(r['seconds']):.3g} |")
    sys.stdout.flush()
PY
