"""The tables of jigs.md from the JSON of `scalcal jig` (written by jigs_runs.sh)."""
import json
import os
import sys

folder, jigs = sys.argv[1], sys.argv[2:]


def load(jig, c):
    path = os.path.join(folder, f"{jig}-{c}.json")
    text = open(path).read() if os.path.exists(path) else ""
    return json.loads(text) if text.strip() else None


def g(x, digits=6):
    return f"{x:.{digits}g}"


print("| jig | N | D | A | E | S | θ_bias | θ_scale | θ_nonorth |")
print("| --- | ---: | ---: | ---: | ---: | ---: | ---: | ---: | ---: |")
for jig in jigs:
    d = load(jig, "D")
    if d is None:
        err = open(os.path.join(folder, f"{jig}-D.err")).read().strip().split(": ", 2)[-1]
        print(f"| `{jig}` | | {err} | | | | | | |")
        continue
    c = d["criteria_default"]
    print(f"| `{jig}` | {d['positions']} | {g(c['D'], 10)} | {g(c['A'], 7)} | {g(c['E'], 7)} | {g(c['S'], 7)} | "
          f"{g(c['theta_bias'], 5)} | {g(c['theta_scale'], 5)} | {g(c['theta_nonorth'], 5)} |")

print()
print("| jig | criterion | default mounting | best mounting | exact there | θ_bias, θ_scale, θ_nonorth there | ratio to the limit | the limit | how |")
print("| --- | --- | ---: | ---: | --- | --- | ---: | --- | --- |")
for jig in jigs:
    for crit in "DAES":
        r = load(jig, crit)
        if r is None:
            continue
        proven = "proven" if r["limit_claim_proven"] else "numerical"
        exact = r.get("exact", "")
        how = r["value_status"]
        if "starts" in r:
            how += f", {r['hits']}/{r['starts']} starts agree"
        b = r["criteria_best"]
        thetas = ", ".join(g(b[k], 5) for k in ("theta_bias", "theta_scale", "theta_nonorth"))
        print(f"| `{jig}` | {crit} | {g(r['value_default_orientation'], 10)} | {g(r['value'], 10)} | "
              f"{('`' + exact + '`') if exact else ''} | {thetas} | {r['ratio']:.6f} | {r['limit_claim']} ({proven}) | {how} |")

print()
print("Best mountings that differ from the default (rows: the meter's x, y, z axes in jig coordinates):")
print()
for jig in jigs:
    for crit in "AES":
        r = load(jig, crit)
        if r is None or r["value"] >= r["value_default_orientation"] * (1 - 1e-12):
            continue
        o = r.get("orientation_exact") or "; ".join("(" + ", ".join(f"{v:.9f}" for v in row) + ")" for row in r["orientation"])
        print(f"- `{jig}`, {crit}: {o}")
