#!/usr/bin/env python3
"""The embedded library against `scalcal calibrate` on every real log (test side only).

For each log: the CLI's calibration (--json), then the library fed the same samples one by one
into the CLI's own intervals (the samples the CLI excluded left out), in double, in float, and in
long double (the reference: the same algorithm where rounding is 2048 times smaller). The double
build must give every parameter (offset, scale deviations, non-orthogonality, gains, the matrix
relative to its largest entry, the residual-based and the reported standard errors) within 1e-9
relative of the CLI's; where the CLI's own value is farther than that from the reference (its
iteration stops at its rounding floor), the library's must be within 1e-9 of the reference and
no farther from the CLI than the CLI is from the reference. The float build must give every
parameter within a tenth of its standard error. The noise-based quantities (noise, predicted
standard errors) are reported: the library keeps each pose's scatter matrix, not its samples, and
takes the scatter of the moduli to first order. The program's criteria and the next pose (by D,
A, E, S among the 26 candidates) are checked with `scalcal evaluate` at the library's directions;
the CLI's own efficiencies are reported beside (it judges the program in its estimator's frame,
which the correction's frame differs from by a rotation: the angle is printed). The library's own
detector is then run on the same log and its poses and calibration reported against the CLI's.
Usage: compare_cli.py SCALCAL HOST_RUN_DOUBLE HOST_RUN_FLOAT HOST_RUN_LONG DATA_DIR... ; prints a
table and exits 1 when a check fails."""
import concurrent.futures
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


def rel_all(ours, cli, scale=None):
    """The largest relative difference, each entry relative to itself or to `scale`."""
    worst = 0.0
    for a, b in zip(ours, cli):
        if b is not None:
            worst = max(worst, abs(a - b) / scale if scale else rel(a, b))
    return worst


def compare_exact(log, what, ours, cli, table, tol=1e-9, reference=None, scale=None):
    """ours against the CLI's within tol; with a reference, a larger difference passes when it is the
    CLI's own distance from the reference (ours within tol of it)."""
    worst = rel_all(ours, cli, scale)
    cli_off = rel_all(cli, reference, scale) if reference else None
    ours_off = rel_all(ours, reference, scale) if reference else None
    table.append((log, what, worst, cli_off, ours_off))
    if worst <= tol:
        return
    if reference and ours_off <= tol and worst <= cli_off + tol:
        return
    failures.append(f"{log}: {what} differs from the CLI by {worst:.3g} relative (> {tol:g})" +
                    (f"; the CLI is {cli_off:.3g} and the library {ours_off:.3g} from the reference" if reference else ""))


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


def corrected_directions(r):
    """The poses' directions through a calibration printed by host_run: matrix (mean - offset), normalised."""
    M, o, out = r["matrix"], r["offset"], []
    for p in r["pose"]:
        d = [p[4 + k] - o[k] for k in range(3)]
        c = [sum(M[3 * i + k] * d[k] for k in range(3)) for i in range(3)]
        n = math.sqrt(sum(x * x for x in c))
        out.append([x / n for x in c])
    return out


def frame_angle(cli):
    """The largest angle (degrees) between the CLI's program directions and its correction's frame."""
    M, o, worst = cli["matrix"], cli["offset"], 0.0
    for iv in cli["intervals"]:
        d = [iv["mean"][k] - o[k] for k in range(3)]
        c = [sum(M[i][k] * d[k] for k in range(3)) for i in range(3)]
        n = math.sqrt(sum(x * x for x in c))
        dot = sum(c[k] / n * iv["direction"][k] for k in range(3))
        worst = max(worst, math.degrees(math.acos(min(1.0, dot))))
    return worst


def check_log(scalcal, host_double, host_float, host_long, path, name, rate, magnitude, table, notes):
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
    ref = host_result(host_long, [path, "--intervals", given] + args)
    os.unlink(given)
    for r, precision in ((d, "double"), (fl, "float"), (ref, "long double")):
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
    # Double: every parameter within 1e-9 relative (or the CLI's own distance from the reference).
    matrix = [v for row in cli["matrix"] for v in row]
    largest = max(abs(v) for v in matrix)
    exact = [("offset", d["offset"], cli["offset"], ref["offset"], None),
             ("matrix (relative to its largest entry)", d["matrix"], matrix, ref["matrix"], largest),
             ("scale_deviation", d["scale_deviation"], cli["scale_deviation"], ref["scale_deviation"], None),
             ("gain", d["gain"], cli["gain"], ref["gain"], None),
             ("nominal_gain", d["nominal_gain"], [cli["nominal_gain"]], ref["nominal_gain"], None),
             ("residual_rms", d["residual_rms"], [cli["residual_rms"]], ref["residual_rms"], None),
             ("achieved_std", d["achieved_std"], [cli["achieved_std"][n] for n in NAMES[:P]], ref["achieved_std"], None)]
    if P == 9:
        exact.insert(3, ("nonorthogonality", d["nonorthogonality"], cli["nonorthogonality"], ref["nonorthogonality"],
                         None))
    for key in ("bias_std", "scale_deviation_std", "nonorthogonality_std", "gain_std"):
        if (P < 6 and key != "bias_std") or (P < 9 and key == "nonorthogonality_std"):
            continue
        exact.append((key + " (the larger)", d[key], cli[key], ref[key], None))
    for what, ours, theirs, reference, scale in exact:
        compare_exact(name, what, ours, theirs, table, reference=reference, scale=scale)
    # The noise-based quantities: first order in the pose scatter (reported, bounded loosely).
    compare_exact(name, "noise (first order)", d["noise"], [cli["noise"]], table, tol=5e-2)
    compare_exact(name, "predicted_std (first order)", d["predicted_std"],
                  [cli["predicted_std"][n] for n in NAMES[:P]], table, tol=5e-2)
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
    table.append((name, "float: |float - CLI| / standard error", worst, None, None))
    if not worst <= 0.1:
        failures.append(f"{name}: the float build is {worst:.3g} standard errors from the CLI (> 0.1)")
    # Guidance: the program's criteria and the next pose against `scalcal evaluate` at the library's
    # directions; the CLI's efficiencies beside (its program is judged in its estimator's frame).
    directions = corrected_directions(d)
    compare_exact(name, "program D A E S (scalcal evaluate)", d["program_value"],
                  [evaluate(scalcal, cli["model"], directions, c) for c in CRITERIA], table)
    table.append((name, "efficiency D A E S against the CLI's (report)",
                  rel_all(d["program_efficiency"], [cli["program"]["efficiency"][c] for c in CRITERIA]), None, None))
    notes.append(f"{name}: the CLI's program directions are {frame_angle(cli):.2g} degrees from its correction's frame")
    for crit, best, after in d["next_pose"]:
        c = CRITERIA[int(crit)]
        with concurrent.futures.ThreadPoolExecutor(max_workers=os.cpu_count() or 2) as pool:
            values = list(pool.map(lambda x: evaluate(scalcal, cli["model"], directions + [list(x)], c), CANDIDATES))
        compare_exact(name, f"next pose by {c}: criterion after", [float(after)], [values[int(best)]], table)
        if min(values) < values[int(best)] * (1 - 1e-9):
            failures.append(f"{name}: candidate {values.index(min(values))} is better by {c} than {best}, the one chosen")
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
    if len(sys.argv) < 6:
        raise SystemExit(__doc__)
    scalcal, host_double, host_float, host_long = sys.argv[1:5]
    dirs = sys.argv[5:]
    table, notes = [], []
    for name, file, rate, magnitude in LOGS:
        path = next((os.path.join(d, file) for d in dirs if os.path.exists(os.path.join(d, file))), None)
        if not path:
            notes.append(f"{name}: {file} not found in {', '.join(dirs)}: skipped")
            continue
        check_log(scalcal, host_double, host_float, host_long, path, name, rate, magnitude, table, notes)
    print("%-10s %-46s %12s %14s %14s" % ("log", "quantity", "lib - CLI", "CLI - ref.", "lib - ref."))
    for log, what, worst, cli_off, ours_off in table:
        print("%-10s %-46s %12.3g %14s %14s" % (log, what, worst, "" if cli_off is None else "%.3g" % cli_off,
                                                 "" if ours_off is None else "%.3g" % ours_off))
    for n in notes:
        print(n)
    for f in failures:
        print("FAIL", f)
    print("CLI equality: %s" % ("FAILED" if failures else "passed"))
    return 1 if failures else 0


if __name__ == "__main__":
    sys.exit(main())
