#!/usr/bin/env bash
# Regenerates experiments/docs/attainment.md: the sweep's best program for every N and criterion
# (seed 1, default starts), each run through `scalcal certify`. Where the sweep's program stays
# numerical and proofs/designs/ holds a closed-form design of that N (D at N = 14: d3_14.csv), the
# row certifies that design instead and says so. Usage:
#   attainment_runs.sh [A..B] [CRITERIA]      (default 9..40 D,A,E,S)
# from the repository root after scripts/build.sh; writes the table to stdout.
set -euo pipefail
range="${1:-9..40}"
criteria="${2:-D,A,E,S}"
scalcal="${SCALCAL:-build/experiments/scalcal}"
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
"$scalcal" sweep --positions "$range" --criteria "$criteria" --seed 1 --out "$work/sweep.csv" >/dev/null
/usr/bin/python3 - "$work" "$scalcal" <<'PY'
import csv, json, subprocess, sys
work, scalcal = sys.argv[1], sys.argv[2]
designs = {("D", "14"): "proofs/designs/d3_14.csv"}
rows = list(csv.DictReader(open(f"{work}/sweep.csv")))
def certify(path, criterion):
    out = subprocess.run([scalcal, "certify", path, "--criterion", criterion, "--json"],
                         check=True, capture_output=True, text=True).stdout
    return json.loads(out)
print("| crit | N | best value | status | radius / enclosure | certify s | sweep s |")
print("| --- | --- | --- | --- | --- | --- | --- |")
for r in rows:
    path = f"{work}/{r['criterion']}{r['positions']}.csv"
    with open(path, "w") as f:
        f.write("x,y,z\n")
        for p in r["program"].split(";"):
            f.write(",".join(p.split()) + "\n")
    j = certify(path, r["criterion"])
    note = ""
    design = designs.get((r["criterion"], r["positions"]))
    if j["status"] == "limit attained, numerical" and design:
        note = f" ({design}; the sweep's program: {j['reason']})"
        j = certify(design, r["criterion"])
    if j["status"] == "missed, certified local optimum":
        lo, hi = j["enclosure"]
        shown = f"[{lo[:36]}..., {hi[:36]}...] ({j['enclosure_digits']} digits)"
    elif j["radius"]:
        shown = f"radius {j['radius']}"
    else:
        shown = j["reason"]
    shown += note
    print(f"| {r['criterion']} | {r['positions']} | {float(r['value']):.10g} | {j['status']} | {shown} | "
          f"{j['seconds']:.3f} | {float(r['seconds']):.3g} |")
    sys.stdout.flush()
PY
