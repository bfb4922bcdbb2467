#!/bin/sh
# Re-makes the tables of regions.md: sh experiments/docs/regions_runs.sh BUILD_DIR
# (prints Markdown; needs python3 for the JSON, any version). Takes about 20 minutes on 2 cores:
# the certified limits are seconds per region, the smallest-N sweeps most of it.
set -e
S=${1:-build}/experiments/scalcal

limits_row() { python3 -c '
import json, sys
d = json.load(sys.stdin)
cells = []
for c in "DAES":
    e = d[c]
    gap = (e["value"] - e["lower_bound"]) / e["value"]
    cells.append("%.6g (%.2g) x%.4g" % (e["value"], max(gap, 0.0), e["relative_to_sphere"]))
print("| `%s` | %s |" % (d["region"], " | ".join(cells)))
'; }

thetas_row() { python3 -c '
import json, sys
d = json.load(sys.stdin)
e = d["D"]
print("| `%s` | %.4g | %.4g | %.4g |" % (d["region"], e["theta_bias"], e["theta_scale"], e["theta_nonorth"]))
'; }

smallest_row() { python3 -c '
import json, sys
rows = json.load(sys.stdin)
region = sys.argv[1]
cells = []
for c in "DAES":
    hit = [r for r in rows if r["criterion"] == c and r["ratio"] <= 1.01]
    cells.append(("%d (%.4f)" % (hit[0]["positions"], hit[0]["ratio"])) if hit else "over 32")
print("| `%s` | %s |" % (region, " | ".join(cells)))
' "$1"; }

CAPS="cap:10 cap:20 cap:30 cap:45 cap:60 cap:90 cap:120 cap:133.6 cap:135 cap:150"
BANDS="band:80:100 band:70:110 band:60:120 band:45:135"
FACES="faces:5 faces:10 faces:20 faces:30 faces:45"

echo "## Limits: value (proven relative gap) x the sphere's"
echo "| region | D | A | E | S |"
echo "| --- | --- | --- | --- | --- |"
for r in $CAPS $BANDS $FACES; do "$S" limits --region "$r" --json | limits_row; done

echo
echo "## RMS errors of the D-optimal measure (N = 1; divide by sqrt(N) for N positions)"
echo "| region | theta_bias | theta_scale | theta_nonorth |"
echo "| --- | --- | --- | --- |"
"$S" limits --json >/dev/null  # the sphere's are those of any 4-design
for r in $CAPS $BANDS $FACES; do "$S" limits --region "$r" --json | thetas_row; done

echo
echo "## Smallest N within 1 % of the region's limit (its ratio), N = 9..32, 4 starts"
echo "| region | D | A | E | S |"
echo "| --- | --- | --- | --- | --- |"
for r in cap:30 cap:60 cap:90 band:60:120 faces:10 faces:20; do
  "$S" sweep --positions 9..32 --criteria D,A,E,S --region "$r" --starts 4 --json --no-timing | smallest_row "$r"
done

# E and S on caps: the closed forms of proofs/cap_es_limits.md (E up to 110.38 degrees, S up to 99.88;
# lower bounds beyond) against the solver's value and proven lower bound.
closed_row() { python3 -c '
import json, math, sys
d = json.load(sys.stdin)
c = math.cos(math.radians(float(sys.argv[1])))
exact = {"E": (3*c**4 + 36*c**3 + 194*c**2 + 260*c + 147) / (1 - c)**4, "S": ((3 + c) / (1 - c))**4}
reach = {"E": float(sys.argv[1]) <= 110.3755, "S": float(sys.argv[1]) <= 99.8793}
cells = []
for k in "ES":
    e = d[k]
    cells.append("%.9g%s | %+.2g | %+.2g" % (exact[k], "" if reach[k] else " (bound)",
                 e["value"] / exact[k] - 1, e["lower_bound"] / exact[k] - 1))
print("| `%s` | %s |" % (d["region"], " | ".join(cells)))
' "$1"; }

echo
echo "## E and S on caps: closed form against the solver (relative differences)"
echo "| region | E closed form | solver value | solver bound | S closed form | solver value | solver bound |"
echo "| --- | --- | --- | --- | --- | --- | --- |"
for a in 10 20 30 45 60 90 100 110 120; do "$S" limits --region "cap:$a" --json | closed_row "$a"; done
