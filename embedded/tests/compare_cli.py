#!/usr/bin/env python3
"""The embedded library against `scalcal calibrate` on every real log (test side only).

For each log: the CLI's calibration (--json, its detection chosen adaptively as users get it), then
the library fed the same samples one by one: the CLI's own intervals, without the breaks inside them
(noisy windows) and the samples it excluded as outliers; in double, in float, and in long double (the
reference: the same algorithm where rounding is 2048 times smaller). The double build must give
every parameter (offset, scale deviations, non-orthogonality, gains, the matrix relative to its
largest entry, the residual-based standard errors) within 1e-9 relative of the CLI's; where the
CLI's own value is farther than that from the reference (its iteration stops at its rounding
floor), the library's must be within 1e-9 of the reference and no farther from the CLI than the
CLI is from the reference. The between-pose error model (REML, the CLI's model_std and the
standard errors it reports) is compared the same way with the library given the CLI's noise within
poses (--noise): the library takes that noise from each pose's scatter matrix to first order (it
keeps no samples), so with its own noise the noise-based quantities are reported, bounded loosely.
The float build (its own noise, as on a device) must give every parameter within a tenth of the
CLI's standard error. The program's criteria and the next pose (by D, A, E, S among the 26
candidates) are checked with `scalcal evaluate` at the library's directions; the CLI's own
efficiencies are reported beside. The library's own detector is then run on the same log and
compared, as a looser check, with the CLI run on the detector's parameters (--window 1
--threshold-factor 6 --min-interval 1): poses within one, calibration within half a standard error.
The detector's moving share (its windows above 3 times its floor) is compared with the CLI's `motion`
(within 0.05). The CLI calibrates the real magnetometer log (QMC5883L) tumbling, every sample a
position: the library's still-pose path must refuse it (SCALCAL_E_MOVING, the stream moves in more
than 3/4 of its windows), and a still-pose magnetometer log simulated by `scalcal simulate` (seeded)
takes its place in the still-pose comparison. The library's tumbling mode (scalcal/tumble.h: 64
cells, every sample in one) is compared with the CLI's tumbling fit on the QMC5883L log and on the
rehearsal of docs/magnetometer.md (seeded), without and with its two disturbances (three passes, each
gated by the last): every parameter within one of the library's own standard errors of the CLI's
(1.5 with the disturbances; it keeps 64 cells, not 6000-22743 samples: on the rehearsals the
differences are the decimation's; on the QMC5883L log, 3.2 of the CLI's standard errors: the CLI takes off
the noise's bias, which is anisotropic once corrected, and the library's cells keep part of it:
tests/anisotropic_noise.py), the noise-based standard errors within 12 % of the CLI's, float within
0.01 of the CLI's standard errors of double. A gyro on a rate table (scalcal/rate_table.h) is compared on
seeded rehearsals (RATE_TABLES): on the CLI's segments and rests, double within 1e-6 relative and float within
a tenth of a standard error; through the detector within RATE_TABLE_DETECTOR standard errors; its logs cut to
one rest and to none refused.
Usage: compare_cli.py SCALCAL HOST_RUN_DOUBLE HOST_RUN_FLOAT HOST_RUN_LONG DATA_DIR... ; prints a
table and exits 1 when a check fails."""
import concurrent.futures
import json
import math
import os
import subprocess
import sys
import tempfile

LOGS = [  # name, file, the CLI's options besides --magnitude, --magnitude
    ("xsens", "xsens_acc.txt", [], "9.81744"),
    ("mpu6050", "mpu6050_acc.csv", ["--rate", "100"], "9.80665"),
    ("nilspod", "nilspod_ferraris_acc.csv", ["--rate", "102.4"], "9.80665"),
]
# The real magnetometer log: the CLI calibrates it tumbling (reported, not compared).
TUMBLING = ("qmc5883l", "qmc5883l_mag.csv", ["--rate", "50"], "auto")
# Its stand-in: a magnetometer held still on the 20 icosahedral poses, 3 s each at 50 Hz, in counts
# of a 400-count field with 0.5 % noise per axis and 5 % errors (seeded: the same log every run).
# The CLI's `mag` takes every sample of a log as a position; its still-pose path is --instrument accel.
SIMULATED = ("mag (simulated)", ["simulate", "--program", "icosahedral-20", "--noise", "0.005", "--magnitude", "400",
                                 "--size", "0.05", "--seed", "5", "--rate", "50", "--dwell", "3", "--still", "10"],
             ["--instrument", "accel"], "auto")
# The tumbling comparisons: name, the log (a file, or `scalcal simulate` arguments), the CLI's options
# besides --magnitude, --magnitude, the library's gated passes (1: none), the bound on |lib - CLI| in the
# library's standard errors (the disturbed log's 1.5: the CLI grows each disturbed stretch over its
# neighbours beyond 2.5 robust scales and leaves out 249 samples, the library's gate at 5 scales 179).
REHEARSAL = ["simulate", "--tumble", "120", "--rate", "50", "--noise", "0.005", "--magnitude", "50", "--size", "0.1",
             "--seed", "3"]
TUMBLING_FITS = [
    ("qmc5883l tumbling", "qmc5883l_mag.csv", ["--rate", "50"], "auto", 1, 1.0),
    ("rehearsal tumbling", REHEARSAL, [], "50", 1, 1.0),
    ("rehearsal, 2 disturbances", REHEARSAL + ["--disturbances", "2"], [], "50", 3, 1.5),
]
# A gyro on a rate table (scalcal/rate_table.h): name, `scalcal simulate --instrument gyro` arguments
# (seeded), the table's rate. The CLI's own segments and rests given to the library (double within 1e-6
# relative of the CLI, float within a tenth of its standard errors); then the library's detector on
# the same log (within RATE_TABLE_DETECTOR of the CLI's standard errors: its 1 s window closes
# slightly different segments than the CLI's adaptive one); then the log with one rest left (which the
# CLI refuses too: a lone rest is no segment) and with none: the library refuses both.
RATE_TABLES = [
    ("gyro table dodecahedral-12", ["--program", "dodecahedral-12", "--magnitude", "3.14159", "--seed", "1"], "3.14159"),
    ("gyro table classic18", ["--program", "classic18", "--magnitude", "1", "--seed", "2"], "1"),
]
RATE_TABLE_DETECTOR = 1.0
# The streaming detector's parameters (scalcal_detector_options_default), given to the CLI for the
# detector's check.
DETECTOR = ["--window", "1", "--threshold-factor", "6", "--min-interval", "1"]
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
    CLI's own distance from the reference at its rounding floor (at most 1e-6: not a different
    formula), ours within tol of the reference."""
    worst = rel_all(ours, cli, scale)
    cli_off = rel_all(cli, reference, scale) if reference else None
    ours_off = rel_all(ours, reference, scale) if reference else None
    table.append((log, what, worst, cli_off, ours_off))
    if worst <= tol:
        return
    if reference and ours_off <= tol and worst <= cli_off + tol and cli_off <= 1e-6:
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


def calibrate(scalcal, path, args):
    """The CLI's calibration (--json) or (None, its error line)."""
    code, out, err = run([scalcal, "calibrate", "--measurements", path, "--json", "--suggest", "0"] + args)
    return (json.loads(out), None) if code == 0 else (None, f"exit {code}: {err.strip()}")


def given_samples(cli):
    """host_run's --intervals file: the CLI's intervals, the breaks inside them, its outliers."""
    with tempfile.NamedTemporaryFile("w", suffix=".txt", delete=False) as f:
        for iv in cli["intervals"]:
            f.write("%r %r\n" % (iv["start"], iv["end"]))
            for first, last in iv["breaks"]:
                f.write("break %d %d\n" % (first, last))
        for line in cli["excluded_samples"]:
            f.write("exclude %d\n" % line)
        return f.name


def model_of(cli, P):
    """The CLI's error-model quantities in host_run's order (None where the model did not apply)."""
    return [cli["model_std"][n] for n in NAMES[:P]], cli["between_pose_std"]


def reported_std(P):
    """The reported standard errors of a P-parameter model."""
    keys = ["bias_std"]
    if P >= 6:
        keys += ["scale_deviation_std", "gain_std"]
    if P == 9:
        keys.append("nonorthogonality_std")
    return keys


def compare_parameters(name, d, ref, cli, P, table):
    """Double against the CLI, 1e-9 relative (or the CLI's own distance from the reference)."""
    matrix = [v for row in cli["matrix"] for v in row]
    largest = max(abs(v) for v in matrix)
    exact = [("offset", d["offset"], cli["offset"], ref["offset"], None),
             ("matrix (relative to its largest entry)", d["matrix"], matrix, ref["matrix"], largest),
             ("scale_deviation (relative to 1)", d["scale_deviation"], cli["scale_deviation"], ref["scale_deviation"], 1),
             ("gain", d["gain"], cli["gain"], ref["gain"], None),
             ("nominal_gain", d["nominal_gain"], [cli["nominal_gain"]], ref["nominal_gain"], None),
             ("residual_rms", d["residual_rms"], [cli["residual_rms"]], ref["residual_rms"], None),
             ("achieved_std", d["achieved_std"], [cli["achieved_std"][n] for n in NAMES[:P]], ref["achieved_std"], None)]
    if P == 9:
        exact.insert(3, ("nonorthogonality (radians, relative to 1)", d["nonorthogonality"], cli["nonorthogonality"],
                         ref["nonorthogonality"], 1))
    for what, ours, theirs, reference, scale in exact:
        compare_exact(name, what, ours, theirs, table, reference=reference, scale=scale)
    # Each relative to itself (report): where the estimator stops, both stop at the residual's
    # rounding floor, which leaves X (gains relative to 1) uncertain by about 1e-10.
    deviations = [("scale_deviation", "scale_deviation")] + ([("nonorthogonality", "nonorthogonality")] if P == 9 else [])
    for key, _ in deviations:
        table.append((name, key + " (relative to itself, report)", rel_all(d[key], cli[key]), rel_all(cli[key], ref[key]),
                      rel_all(d[key], ref[key])))


def compare_errors(name, d, ref, own, cli, P, table):
    """The standard errors: d and ref were given the CLI's noise within poses where the CLI used it,
    own took its own (first order)."""
    modelled = all(v == "model" for v in cli["std_from"].values())
    if modelled != (int(d["error_model"][0]) == 1):
        failures.append(f"{name}: the error model {'applies' if modelled else 'does not apply'} in the CLI, "
                        f"error_model {int(d['error_model'][0])} in the library")
        return
    given = "(the CLI's noise)" if cli["within_pose_std"] is not None else "(no noise within poses)"
    if modelled:
        model_std, between = model_of(cli, P)
        compare_exact(name, "model_std " + given, d["model_std"], model_std, table, reference=ref["model_std"])
        compare_exact(name, "between_pose_std " + given, d["between_std"], [between], table,
                      reference=ref["between_std"])
        compare_exact(name, "predicted_std " + given, d["predicted_std"],
                      [cli["predicted_std"][n] for n in NAMES[:P]], table, reference=ref["predicted_std"])
        compare_exact(name, "model_std (own noise, first order)", own["model_std"], model_std, table, tol=5e-2)
        compare_exact(name, "between_pose_std (own noise, first order)", own["between_std"], [between], table,
                      tol=5e-2)
    for key in reported_std(P):
        compare_exact(name, key + " (reported) " + given, d[key], cli[key], table, reference=ref[key])
    # The noise-based quantities with the library's own noise: first order in the pose scatter.
    compare_exact(name, "noise (own, first order)", own["noise"], [cli["noise"]], table, tol=5e-2)
    compare_exact(name, "predicted_std (own noise, first order)", own["predicted_std"],
                  [cli["predicted_std"][n] for n in NAMES[:P]], table, tol=5e-2)


def standard_errors_apart(r, cli, P):
    """The largest |r - CLI| over the CLI's reported standard error, every parameter."""
    pairs = [("offset", "bias_std")]
    if P >= 6:
        pairs += [("scale_deviation", "scale_deviation_std"), ("gain", "gain_std")]
    if P == 9:
        pairs.append(("nonorthogonality", "nonorthogonality_std"))
    return max(abs(a - b) / se for key, std_key in pairs for a, b, se in zip(r[key], cli[key], cli[std_key]))


def check_guidance(scalcal, name, d, cli, table, notes):
    """The program's criteria and the next pose against `scalcal evaluate` at the library's directions;
    the CLI's efficiencies beside (its program is judged in its estimator's frame)."""
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


def check_detector(scalcal, host_double, path, name, cli_args, host_args, notes):
    """The library's detector against the CLI on the detector's parameters: poses within one,
    calibration within half a standard error."""
    cli, err = calibrate(scalcal, path, cli_args + DETECTOR)
    if cli is None:
        failures.append(f"{name}: scalcal calibrate {' '.join(DETECTOR)}: {err}")
        return
    det = host_result(host_double, [path, "--detect"] + host_args)
    poses = int(det["poses"][0])
    notes.append(f"{name}: detector {poses} poses (CLI on the same parameters {cli['positions']}), floor "
                 f"{det['detector_floor'][0]:.4g} (CLI {cli['noise_floor']:.4g}), status {' '.join(det['status'][0][1:])}")
    check_moving_share(name, det, cli, notes)
    if abs(poses - cli["positions"]) > 1:
        failures.append(f"{name}: the detector finds {poses} poses, the CLI on its parameters {cli['positions']}")
    if det["status"][0][0] != "0" or int(det["model"][0]) != MODELS[cli["model"]]:
        failures.append(f"{name}: the detector's poses give {' '.join(det['status'][0][1:])}, model "
                        f"{int(det['model'][0])}; the CLI {cli['model']}")
        return
    worst = standard_errors_apart(det, cli, MODELS[cli["model"]])
    notes.append(f"{name}: detector's calibration within {worst:.3g} standard errors of the CLI's on its parameters")
    if not worst <= 0.5:
        failures.append(f"{name}: the detector's calibration is {worst:.3g} standard errors from the CLI's (> 0.5)")


def check_moving_share(name, det, cli, notes):
    """The detector's share of moving windows against the CLI's moving share (its `motion`)."""
    judged, moving = (int(v) for v in det["detector_windows"])
    share = moving / judged if judged else float("nan")
    notes.append(f"{name}: the detector's windows move {100 * share:.1f} % of the time (the CLI: "
                 f"{100 * cli['motion']['moving_share']:.1f} %)")
    if not abs(share - cli["motion"]["moving_share"]) <= 0.05:
        failures.append(f"{name}: the detector's moving share {share:.3f}, the CLI's {cli['motion']['moving_share']:.3f}")
    return share


def check_log(hosts, path, name, cli_args, magnitude, table, notes):
    scalcal, host_double, host_float, host_long = hosts
    cli_args = ["--magnitude", magnitude] + cli_args
    host_args = [a for a in cli_args if a not in ("--instrument", "accel")]
    cli, err = calibrate(scalcal, path, cli_args)
    if cli is None:
        failures.append(f"{name}: scalcal calibrate {err}")
        return
    P = MODELS[cli["model"]]
    given = given_samples(cli)
    noise = ["--noise", repr(cli["within_pose_std"])] if cli["within_pose_std"] is not None else []
    d = host_result(host_double, [path, "--intervals", given] + host_args + noise)
    ref = host_result(host_long, [path, "--intervals", given] + host_args + noise)
    own = host_result(host_double, [path, "--intervals", given] + host_args)
    fl = host_result(host_float, [path, "--intervals", given] + host_args)
    os.unlink(given)
    for r, precision in ((d, "double"), (fl, "float"), (ref, "long double"), (own, "double, own noise")):
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
    choice = cli.get("detection_choice") or {}
    notes.append(f"{name}: {cli['positions']} poses, {cli['samples']} samples (the CLI's detection: window "
                 f"{choice.get('window_seconds')} s, threshold factor {choice.get('threshold_factor')}, minimum "
                 f"{choice.get('min_interval_seconds')} s; {sum(len(iv['breaks']) for iv in cli['intervals'])} breaks)")
    compare_parameters(name, d, ref, cli, P, table)
    compare_errors(name, d, ref, own, cli, P, table)
    if cli["iterations"] != int(d["iterations"][0]):
        notes.append(f"{name}: {int(d['iterations'][0])} iterations, the CLI {cli['iterations']}")
    worst = standard_errors_apart(fl, cli, P)
    table.append((name, "float: |float - CLI| / standard error", worst, None, None))
    if not worst <= 0.1:
        failures.append(f"{name}: the float build is {worst:.3g} standard errors from the CLI (> 0.1)")
    check_guidance(scalcal, name, d, cli, table, notes)
    check_detector(scalcal, host_double, path, name, cli_args, host_args, notes)


def check_tumbling(hosts, path, notes):
    """The real magnetometer log: the CLI calibrates it tumbling; the library's detector must refuse it
    as moving (SCALCAL_E_MOVING), with the CLI's moving share."""
    scalcal, host_double = hosts[0], hosts[1]
    name, _, args, magnitude = TUMBLING
    cli, err = calibrate(scalcal, path, ["--magnitude", magnitude] + args)
    if cli is None:
        failures.append(f"{name}: scalcal calibrate {err}")
        return
    if not cli["tumbling"]:
        failures.append(f"{name}: the CLI no longer calibrates it tumbling: compare it as a still-pose log")
        return
    for binary in hosts[1:3]:
        det = host_result(binary, [path, "--detect", "--magnitude", magnitude] + args)
        share = check_moving_share(f"{name} ({det['precision'][0]})", det, cli, notes)
        notes.append(f"{name} ({det['precision'][0]}): the CLI calibrates it tumbling ({cli['samples']} samples as "
                     f"positions); the library's detector closes {int(det['poses'][0])} poses and the fit says: "
                     f"{' '.join(det['status'][0][1:])}")
        if det["status"][0][0] != "11" or not share > 0.75:
            failures.append(f"{name}: the library does not refuse the tumbling log as moving: "
                            f"{' '.join(det['status'][0][1:])}, moving share {share:.3f}")


def check_tumbling_fit(hosts, path, name, cli_args, magnitude, passes, bound, table, notes):
    """The tumbling mode against the CLI's tumbling fit of every sample."""
    scalcal, host_double, host_float = hosts[0], hosts[1], hosts[2]
    cli, err = calibrate(scalcal, path, ["--magnitude", magnitude] + cli_args)
    if cli is None or not cli.get("tumbling"):
        failures.append(f"{name}: scalcal calibrate does not fit it tumbling: {err}")
        return
    args = [path, "--tumble", "--magnitude", magnitude] + cli_args + (["--gate", "5", "--passes", str(passes)]
                                                                       if passes > 1 else [])
    results = {}
    for binary in (host_double, host_float):
        r = host_result(binary, args)
        precision = r["precision"][0]
        if r["status"][0][0] != "0" or int(r["model"][0]) != MODELS[cli["model"]]:
            failures.append(f"{name} ({precision}): {' '.join(r['status'][0][1:])}, model {int(r['model'][0])}; "
                            f"the CLI {cli['model']}")
            return
        results[precision] = r
    d, fl = results["double"], results["float"]
    own, in_cli, std_ratio, float_apart = 0, 0, [], 0
    for key, std in (("offset", "bias_std"), ("scale_deviation", "scale_deviation_std"),
                     ("nonorthogonality", "nonorthogonality_std"), ("gain", "gain_std")):
        for k in range(3):
            ours, theirs, e = float(d[key][k]), cli[key][k], cli[std][k]
            own = max(own, abs(ours - theirs) / float(d[std][k]))
            in_cli = max(in_cli, abs(ours - theirs) / e)
            std_ratio.append(float(d[std][k]) / e)
            float_apart = max(float_apart, abs(float(fl[key][k]) - ours) / e)
    predicted = [float(x) / y for x, y in zip(d["predicted_std"], cli["predicted_std"].values())]
    table.append((name, "tumbling: max |lib - CLI| / lib's std", own, None, None))
    table.append((name, "tumbling: max |lib - CLI| / CLI's std", in_cli, None, None))
    table.append((name, "tumbling: float - double, CLI's std", float_apart, None, None))
    disturbed = int(d["tumble_disturbed"][-1])
    notes.append(f"{name}: {cli['samples']} samples, the CLI leaves out "
                 f"{sum(x['samples'] for x in cli['tumbling']['disturbed'])}; the library {disturbed} "
                 f"({passes} pass{'es' if passes > 1 else ''}) in {int(d['tumble_cells'][0])} cells "
                 f"({int(d['tumble_merges'][-1])} merges); standard errors lib / CLI "
                 f"{min(std_ratio):.3g}..{max(std_ratio):.3g} (the CLI's Newey-West widening "
                 f"{cli['tumbling']['correlation_factor']:.3g}), noise-based {min(predicted):.3g}..{max(predicted):.3g}; "
                 f"noise {float(d['noise'][0]):.4g} (CLI {cli['noise']:.4g}), residual RMS "
                 f"{float(d['residual_rms'][0]):.4g} (CLI {cli['residual_rms']:.4g}); {int(d['iterations'][0])} "
                 f"iterations (CLI {cli['iterations']})")
    if not own <= bound:
        failures.append(f"{name}: the tumbling mode is {own:.3g} of its standard errors from the CLI (> {bound})")
    if not all(0.88 <= x <= 1.12 for x in predicted):
        failures.append(f"{name}: noise-based standard errors {min(predicted):.3g}..{max(predicted):.3g} of the CLI's")
    if not float_apart <= 0.01:
        failures.append(f"{name}: float is {float_apart:.3g} of the CLI's standard errors from double (> 0.01)")


def check_rate_table(hosts, tmp, name, simulate, rate, table, notes):
    scalcal = hosts[0]
    path = os.path.join(tmp, "table.csv")
    code, _, err = run([scalcal, "simulate", "--instrument", "gyro", "--noise", "1e-3", "--dwell", "10"] + simulate +
                       ["--log", path, "--truth", os.path.join(tmp, "truth.json")])
    if code != 0:
        failures.append(f"{name}: scalcal simulate exit {code}: {err.strip()}")
        return
    code, out, err = run([scalcal, "calibrate", "--instrument", "gyro", "--measurements", path, "--magnitude", rate,
                          "--json"])
    if code != 0:
        failures.append(f"{name}: scalcal calibrate exit {code}: {err.strip()}")
        return
    cli = json.loads(out)
    spans = sorted((x["start"], x["end"]) for x in cli["segments"] + cli["rests"])
    given = os.path.join(tmp, "intervals.txt")
    with open(given, "w") as f:
        f.writelines("%.17g %.17g\n" % s for s in spans)
    se = [cli["standard_error"][n] for n in NAMES]
    want = cli["offset"] + cli["gain"] + cli["nonorthogonality"]
    for binary, precision, how in ((hosts[1], "double", ["--intervals", given]), (hosts[2], "float", ["--intervals", given]),
                                   (hosts[1], "double, detector", ["--detect"]),
                                   (hosts[2], "float, detector", ["--detect"])):
        r = host_result(binary, [path, "--rate-table", rate] + how)
        label = f"{name} ({precision})"
        if r["status"][0][0] != "0":
            failures.append(f"{label}: the library refused: {' '.join(r['status'][0][1:])}")
            continue
        if (int(r["segments"][0]), int(r["rests"][0])) != (len(cli["segments"]), len(cli["rests"])):
            failures.append(f"{label}: {int(r['segments'][0])} segments and {int(r['rests'][0])} rests, the CLI "
                            f"{len(cli['segments'])} and {len(cli['rests'])}")
        if int(r["model"][0]) != MODELS[cli["model"]]:
            failures.append(f"{label}: model {int(r['model'][0])}, the CLI {cli['model']}")
            continue
        ours = r["offset"] + r["gain"] + r["nonorthogonality"]
        apart = max(abs(a - b) / s for a, b, s in zip(ours, want, se))
        if precision == "double":
            compare_exact(name, "rate table: o, k, gamma (given intervals)", ours, want, table, tol=1e-6)
            compare_exact(name, "rate table: standard errors", r["standard_error"], se, table, tol=1e-6)
            compare_exact(name, "rate table: matrix", r["matrix"], sum(cli["matrix"], []), table, tol=1e-6)
            compare_exact(name, "rate table: noise", r["noise"], [cli["noise"]], table, tol=1e-6)
        bound = 0.1 if precision == "float" else RATE_TABLE_DETECTOR
        table.append((name, f"rate table {precision}: |lib - CLI| / CLI's std", apart, None, None))
        if precision != "double" and apart > bound:
            failures.append(f"{label}: {apart:.3g} of the CLI's standard errors from it (> {bound})")
    # The rests taken out but the first (a lone rest: the CLI refuses it too), then all.
    with open(path) as f:
        head, *rows = f.read().splitlines()
    first_rest_end = cli["rests"][0]["end"] + 0.5
    for label, keep in (("one rest", lambda t, w: w != 0 or t <= first_rest_end), ("no rest", lambda t, w: w != 0)):
        cut = os.path.join(tmp, "cut.csv")
        with open(cut, "w") as f:
            f.write("\n".join([head] + [x for x in rows if keep(float(x.split(",")[0]), float(x.split(",")[4]))]) + "\n")
        for binary in hosts[1:3]:
            r = host_result(binary, [cut, "--rate-table", rate, "--detect"])
            if r["status"][0][0] == "0":
                failures.append(f"{name}, {label}: the library calibrated a table log without two rests")
            else:
                notes.append(f"{name}, {label} ({'double' if binary == hosts[1] else 'float'}): refused, "
                             f"{' '.join(r['status'][0][1:])}")


def main():
    if len(sys.argv) < 6:
        raise SystemExit(__doc__)
    hosts = sys.argv[1:5]
    dirs = sys.argv[5:]
    table, notes = [], []
    find = lambda file: next((os.path.join(d, file) for d in dirs if os.path.exists(os.path.join(d, file))), None)
    for name, file, args, magnitude in LOGS:
        path = find(file)
        if not path:
            notes.append(f"{name}: {file} not found in {', '.join(dirs)}: skipped")
            continue
        check_log(hosts, path, name, args, magnitude, table, notes)
    with tempfile.TemporaryDirectory() as tmp:
        name, simulate, args, magnitude = SIMULATED
        path = os.path.join(tmp, "mag.csv")
        code, _, err = run([hosts[0]] + simulate + ["--log", path])
        if code != 0:
            failures.append(f"{name}: scalcal simulate exit {code}: {err.strip()}")
        else:
            check_log(hosts, path, name, args, magnitude, table, notes)
    path = find(TUMBLING[1])
    if path:
        check_tumbling(hosts, path, notes)
    with tempfile.TemporaryDirectory() as tmp:
        for name, source, args, magnitude, passes, bound in TUMBLING_FITS:
            if isinstance(source, list):
                path = os.path.join(tmp, "tumble.csv")
                code, _, err = run([hosts[0]] + source + ["--log", path])
                if code != 0:
                    failures.append(f"{name}: scalcal simulate exit {code}: {err.strip()}")
                    continue
            else:
                path = find(source)
                if not path:
                    notes.append(f"{name}: {source} not found in {', '.join(dirs)}: skipped")
                    continue
            check_tumbling_fit(hosts, path, name, args, magnitude, passes, bound, table, notes)
    with tempfile.TemporaryDirectory() as tmp:
        for name, simulate, rate in RATE_TABLES:
            check_rate_table(hosts, tmp, name, simulate, rate, table, notes)
    print("%-16s %-50s %12s %14s %14s" % ("log", "quantity", "lib - CLI", "CLI - ref.", "lib - ref."))
    for log, what, worst, cli_off, ours_off in table:
        print("%-16s %-50s %12.3g %14s %14s" % (log, what, worst, "" if cli_off is None else "%.3g" % cli_off,
                                                 "" if ours_off is None else "%.3g" % ours_off))
    for n in notes:
        print(n)
    for f in failures:
        print("FAIL", f)
    print("CLI equality: %s" % ("FAILED" if failures else "passed"))
    return 1 if failures else 0


if __name__ == "__main__":
    sys.exit(main())
