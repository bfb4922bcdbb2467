#!/usr/bin/env python3
"""The embedded library against `scalcal calibrate` on every real log (test side only).

For each log: the CLI's calibration (--json), then the library fed the same samples one by one
into the CLI's own intervals (the samples the CLI excluded left out): the double build must give
every parameter within 1e-9 relative (offset, matrix, scale deviations, non-orthogonality, gains,
the residual-based standard errors, the program's efficiencies), the float build every parameter
within a tenth of its standard error. The noise-based quantities (noise, predicted standard errors,
chi-square) are reported: the library has each pose's scatter matrix, not its samples, and takes
the scatter of the moduli to first order. The library's own detector is then run on the same log
and its poses and parameters are reported against the CLI's. The guidance's next pose is checked
with `scalcal evaluate`: its criterion after adding the pose, and that no other candidate of the
26 does better. Usage: compare_cli.py SCALCAL HOST_RUN_DOUBLE HOST_RUN_FLOAT DATA_DIR... ; prints
a table and exits 1 when a check fails."""
import json
import math
import os
import subprocess
import sys
import tempfile

LOGS = [  # name, file, --rate, --magnitude
    ("xsens", "xsens_acc.txt", None, "9.81744"),
    ("mpu6050", "mpu6050_acc.csv", "100", "9.80665"),
    ("nilspod", "nilspod_ferraris_acc.csv", "102.4", "9.80665"),
    ("qmc5883l", "qmc5883l_mag.csv", "50", "auto"),
]
MODELS = {"bias3": 3, "axis6": 6, "paper9": 9}
NAMES = ["bias_x", "bias_y", "bias_z", "scale_x", "scale_y", "scale_z", "nonorth_xy", "nonorth_yz", "nonorth_zx"]
CRITERIA = ["D", "A", "E", "S"]
R3, R2 = 1 / math.sqrt(3), 1 / math.sqrt(2)
CANDIDATES = [(1, 0, 0), (-1, 0, 0), (0, 1, 0), (0, -1, 0), (0, 0, 1), (0, 0, -1), (R2, R2, 0), (R2, -R2, 0),
              (-R2, R2, 0), (-R2, -R2, 0), (0, R2, R2), (0, R2, -R2), (0, -R2, R2), (0, -R2, -R2), (R2, 0, R2),
              (-R2, 0, R2), (R2, 0, -R2), (-R2, 0, -R2), (R3, R3, R3), (R3, R3, -R3), (R3, -R3, R3), (R3, -R3, -R3),
              (-R3, R3, R3), (-R3, R3, -R3), (-R3, -R3, R3), (-R3, -R3, -R3)]

failures = []


def run(cmd):
    p = subprocess.run(cmd, capture_output=True, text=True)
    return p.returncode, p.stdout, p.stderr


def host_result(binary, args):
    code, out, err = run([binary] + args)
    if code != 0:
        raise SystemExit(f"{binary} {' '.join(args)}: exit {code}: {err}")
    r = {"pose": []}
    for line in out.splitlines():
        key, *vals = line.split()
        if key == "pose":
            r["pose"].append([float(v) for v in vals])
        elif key in ("status", "next_pose"):
            r.setdefault(key, []).append(vals)
        else:
            try:
                r[key] = [float(v) for v in vals]
            except ValueError:
                r[key] = vals
    return r


def rel(a, b):
    return abs(a - b) / abs(b) if b != 0 else abs(a - b)


def compare_exact(log, what, ours, cli, table, tol=1e-9):
    worst = 0.0
    for a, b in zip(ours, cli):
        if b is None:
            continue
        worst = max(worst, rel(a, b))
    table.append((log, what, worst))
    if not worst <= tol:
        failures.append(f"{log}: {what} differs from the CLI by {worst:.3g} relative (> {tol:g})")


def evaluate(scalcal, model, directions, criterion):
    """The criterion of a program under a model, by `scalcal evaluate` (an independent evaluation)."""
    with tempfile.NamedTemporaryFile("w", suffix=".csv", delete=False) as f:
        f.write("x,y,z\n")
        for d in directions:
            f.write("%.17g,%.17g,%.17g\n" % tuple(d))
        name = f.name
    code, out, err = run([scalcal, "evaluate", name, "--model", model, "--json"])
    os.unlink(name)
    if code != 0:
        raise SystemExit(f"scalcal evaluate: {err}")
    return json.loads(out)[criterion]


def check_log(scalcal, host_double, host_float, path, name, rate, magnitude, table, notes):
    args = ["--magnitude", magnitude] + (["--rate", rate] if rate else [])
    code, out, err = run([scalcal, "calibrate", "--measurements", path, "--json", "--suggest", "0"] + args)
    if code != 0:
        failures.append(f"{name}: scalcal calibrate exit {code}: {err.strip()}")
        return
    cli = json.loads(out)
    P = MODELS[cli["model"]]
    with tempfile.NamedTemporaryFile("w", suffix=".txt", delete=False) as f:
        for iv in cli["intervals"]:
            f.write("%r %r\n" % (iv["start"], iv["end"]))
        for line in cli["excluded_samples"]:
            f.write("exclude %d\n" % line)
        given = f.name
    d = host_result(host_double, [path, "--intervals", given] + args)
    fl = host_result(host_float, [path, "--intervals", given] + args)
    os.unlink(given)
    for r, precision in ((d, "double"), (fl, "float")):
        if r["status"][0][0] != "0":
            failures.append(f"{name} ({precision}): the library refused: {' '.join(r['status'][0][1:])}")
            return
        if int(r["model"][0]) != P:
            failures.append(f"{name} ({precision}): model {int(r['model'][0])} parameters, the CLI {cli['model']}")
            return
    if int(d["poses"][0]) != cli["positions"] or int(d["samples"][0]) != cli["samples"]:
        failures.append(f"{name}: {d['poses']} poses, {d['samples']} samples; the CLI {cli['positions']}, {cli['samples']}")
    if bool(d["started"][0]) != (cli["start"] == "ellipsoid"):
        failures.append(f"{name}: start {d['started']} against the CLI's {cli['start']}")
    # Double: every parameter within 1e-9 relative.
    matrix = [v for row in cli["matrix"] for v in row]
    compare_exact(name, "offset", d["offset"], cli["offset"], table)
    compare_exact(name, "matrix", d["matrix"], matrix, table)
    compare_exact(name, "scale_deviation", d["scale_deviation"], cli["scale_deviation"], table)
    if P == 9:
        compare_exact(name, "nonorthogonality", d["nonorthogonality"], cli["nonorthogonality"], table)
    compare_exact(name, "gain", d["gain"], cli["gain"], table)
    compare_exact(name, "nominal_gain", d["nominal_gain"], [cli["nominal_gain"]], table)
    compare_exact(name, "residual_rms", d["residual_rms"], [cli["residual_rms"]], table)
    compare_exact(name, "achieved_std", d["achieved_std"], [cli["achieved_std"][n] for n in NAMES[:P]], table)
    for key, std_key in (("bias_std", "bias_std"), ("scale_deviation_std", "scale_deviation_std"),
                         ("nonorthogonality_std", "nonorthogonality_std"), ("gain_std", "gain_std")):
        if P < 6 and key != "bias_std" or P < 9 and key == "nonorthogonality_std":
            continue
        compare_exact(name, key + " (the larger)", d[key], cli[std_key], table)
    compare_exact(name, "efficiency D A E S", d["program_efficiency"],
                  [cli["program"]["efficiency"][c] for c in CRITERIA], table)
    # The noise-based quantities: first order in the pose scatter (reported, bounded loosely).
    compare_exact(name, "noise (first order)", d["noise"], [cli["noise"]], table, tol=1e-2)
    compare_exact(name, "predicted_std (first order)", d["predicted_std"],
                  [cli["predicted_std"][n] for n in NAMES[:P]], table, tol=1e-2)
    if cli["iterations"] != int(d["iterations"][0]):
        notes.append(f"{name}: {int(d['iterations'][0])} iterations, the CLI {cli['iterations']}")
    # Float: within a tenth of a standard error.
    worst = 0.0
    pairs = [("offset", "bias_std"), ("scale_deviation", "scale_deviation_std"), ("gain", "gain_std")]
    if P == 9:
        pairs.append(("nonorthogonality", "nonorthogonality_std"))
    if P < 6:
        pairs = [("offset", "bias_std")]
    for key, std_key in pairs:
        for a, b, se in zip(fl[key], cli[key], cli[std_key]):
            worst = max(worst, abs(a - b) / se)
    table.append((name, "float: |float - CLI| / standard error", worst))
    if not worst <= 0.1:
        failures.append(f"{name}: the float build is {worst:.3g} standard errors from the CLI (> 0.1)")
    # Guidance: the next pose by each criterion against `scalcal evaluate` at the CLI's directions.
    directions = [iv["direction"] for iv in cli["intervals"]]
    for crit, best, after in d["next_pose"]:
        c = CRITERIA[int(crit)]
        value = evaluate(scalcal, cli["model"], directions + [list(CANDIDATES[int(best)])], c)
        compare_exact(name, f"next pose by {c}: criterion after", [float(after)], [value], table, tol=1e-8)
        if c == "D":
            values = [evaluate(scalcal, cli["model"], directions + [list(x)], c) for x in CANDIDATES]
            if min(values) < value * (1 - 1e-9):
                failures.append(f"{name}: candidate {values.index(min(values))} is better by D than the one chosen")
    # The library's own detector on the same log.
    det = host_result(host_double, [path, "--detect"] + args)
    notes.append(f"{name}: detector {int(det['poses'][0])} poses (CLI {cli['positions']}), floor "
                 f"{det['detector_floor'][0]:.4g} (CLI {cli['noise_floor']:.4g}), status {' '.join(det['status'][0][1:])}")
    if det["status"][0][0] == "0" and int(det["model"][0]) == P:
        worst = 0.0
        for key, std_key in pairs:
            for a, b, se in zip(det[key], cli[key], cli[std_key]):
                worst = max(worst, abs(a - b) / se)
        notes.append(f"{name}: detector's calibration within {worst:.3g} standard errors of the CLI's")


def main():
    if len(sys.argv) < 5:
        raise SystemExit(__doc__)
    scalcal, host_double, host_float = sys.argv[1:4]
    dirs = sys.argv[4:]
    table, notes = [], []
    for name, file, rate, magnitude in LOGS:
        path = next((os.path.join(d, file) for d in dirs if os.path.exists(os.path.join(d, file))), None)
        if not path:
            notes.append(f"{name}: {file} not found in {', '.join(dirs)}: skipped")
            continue
        check_log(scalcal, host_double, host_float, path, name, rate, magnitude, table, notes)
    print("%-10s %-48s %s" % ("log", "quantity", "max relative difference to the CLI"))
    for log, what, worst in table:
        print("%-10s %-48s %.3g" % (log, what, worst))
    for n in notes:
        print(n)
    for f in failures:
        print("FAIL", f)
    print("CLI equality: %s" % ("FAILED" if failures else "passed"))
    return 1 if failures else 0


if __name__ == "__main__":
    sys.exit(main())
