#!/bin/sh
# Re-makes every table of monte_carlo.md: sh experiments/docs/monte_carlo_runs.sh BUILD_DIR
# (prints Markdown tables; needs python3 for the JSON, any version).
set -e
S=${1:-build}/experiments/scalcal
table() { python3 -c '
import json, sys
mode = sys.argv[1]
d = json.load(sys.stdin)
for r in d["results"]:
    p = {q["name"]: q for q in r["parameters"]}
    te, tt = r["theta_empirical"], r["theta_theoretical"]
    if mode == "theta":
        print("| %s | %d | %s | %.3f / %.3f | %.3f / %.3f | %.3f / %.3f | %.1f%% | %.3f |" % (d["program"], d["positions"], r["modulus"],
              te["bias"], tt["bias"], te["scale"], tt["scale"], te["nonorth"], tt["nonorth"], 100*r["std_sampling_error"], r["max_normalised_cov_difference"]))
    elif mode == "size":
        P = r["parameters"]
        lin = [max(abs(q["linearisation_error"]) for q in P[3*g:3*g+3]) for g in range(3)]
        nb = max(abs(q["noise_bias_in_std_errors"]) for q in P)
        ratio = max(abs(q["std_ratio"] - 1) for q in P)
        print("| %g | %s | %d/%d | %.1e | %.1e | %.1e | %.2f | %.3f | %.3g |" % (d["size"], r["modulus"], r["converged_trials"], d["trials"], lin[0], lin[1], lin[2], nb, ratio, r["mean_iterations"]))
    else:
        dk = [p["scale_" + a]["bias"] for a in "xyz"]
        g = [p["nonorth_" + a]["bias"] for a in ("xy", "yz", "zx")]
        b = [p["bias_" + a]["bias"] for a in "xyz"]
        print("| %g | %s | %s | %s | %s | %.3f | %.3f |" % (d["bench_error_deg"], r["modulus"], " ".join("%+.2e" % v for v in b),
              " ".join("%+.2e" % v for v in dk), " ".join("%+.2e" % v for v in g), max(q["std_ratio"] for q in r["parameters"]), r["mean_noise_ratio"]))
' "$1"; }

echo "## theta: empirical / theoretical (noise 1e-4, 4000 trials, seed 1)"
for p in classic18 rotation-6 nine-2axes nine-3axes dodecahedral-12 icosahedral-20 table1-A table2-E table3-S; do
  $S simulate --program $p --trials 4000 --noise 1e-4 --seed 1 --json | table theta
done
echo "## linearisation range (classic18, noise 1e-4, 2000 trials, seed 2)"
for a in 1e-4 1e-3 3e-3 1e-2 3e-2 0.1 0.2; do
  $S simulate --program classic18 --trials 2000 --noise 1e-4 --size $a --seed 2 --json | table size
done
echo "## bench errors (classic18, noise 1e-4, size 1e-3, 2000 trials, seed 3)"
for e in 0 0.1 0.3 1 3; do
  $S simulate --program classic18 --trials 2000 --noise 1e-4 --bench-error $e --seed 3 --json | table bench
done
