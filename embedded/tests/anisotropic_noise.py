#!/usr/bin/env python3
"""Test side only, run by hand (not by check.sh): the tumbling mode and the CLI's tumbling fit against the truth
on simulated logs of a QMC5883L-like magnetometer (README.md, "Tumbling mode").

The meter: gains 1075, 740.5, 1603 counts per unit field, offsets 6154, 254, 3447 counts, non-orthogonality
0.06, 0.10, 0.01 rad; turned along great circles through random directions at 60 degrees per second, 50 Hz,
22743 samples (as long as the real log). Noise: `equal` (58, 56, 62 counts per axis, about the real sensor's
second-difference noise: anisotropic once corrected) or `proportional` (5.6 % of the field on each axis in its
own gain: isotropic once corrected). Prints, per seed and parameter, (CLI - truth) / CLI's std and (library -
truth) / CLI's std, then the RMS of each and of their difference.
Usage: anisotropic_noise.py SCALCAL HOST_RUN_DOUBLE equal|proportional [SEEDS]"""
import json
import math
import os
import random
import subprocess
import sys
import tempfile

GAIN = [1075.0, 740.5, 1603.0]
OFFSET = [6154.0, 254.0, 3447.0]
GAMMA = [0.06, 0.10, 0.01]


def normalised(v):
    n = math.sqrt(sum(x * x for x in v))
    return [x / n for x in v]


def simulate(path, seed, noise):
    rng = random.Random(seed)
    p = [g / 2 for g in GAMMA]
    phi = [[math.sqrt(1 - p[0] ** 2 - p[2] ** 2), p[0], p[2]], [p[0], math.sqrt(1 - p[0] ** 2 - p[1] ** 2), p[1]],
           [p[2], p[1], math.sqrt(1 - p[2] ** 2 - p[1] ** 2)]]
    G = [[GAIN[i] * phi[i][j] for j in range(3)] for i in range(3)]
    sigma = [58.0, 56.0, 62.0] if noise == "equal" else [0.056 * k for k in GAIN]
    d = normalised([rng.gauss(0, 1) for _ in range(3)])
    step, left, to = math.radians(60 / 50), 0, d
    with open(path, "w") as out:
        out.write("ix,iy,iz\n")
        for _ in range(22743):
            if left <= 0:
                to = normalised([rng.gauss(0, 1) for _ in range(3)])
                left = 1 + int(math.acos(max(-1, min(1, sum(a * b for a, b in zip(d, to))))) / step)
            dot = sum(a * b for a, b in zip(d, to))
            a = [t - dot * x for t, x in zip(to, d)]
            if sum(x * x for x in a) > 1e-20:
                a = normalised(a)
                d = normalised([x * math.cos(step) + y * math.sin(step) for x, y in zip(d, a)])
            left -= 1
            x = [OFFSET[i] + sum(G[i][j] * d[j] for j in range(3)) + sigma[i] * rng.gauss(0, 1) for i in range(3)]
            out.write("%.3f,%.3f,%.3f\n" % tuple(x))


def main():
    if len(sys.argv) < 4 or sys.argv[3] not in ("equal", "proportional"):
        raise SystemExit(__doc__)
    scalcal, host, noise = sys.argv[1:4]
    seeds = int(sys.argv[4]) if len(sys.argv) > 4 else 6
    truth = {"offset": OFFSET, "gain": GAIN, "nonorthogonality": GAMMA}
    zc, zd = [], []
    with tempfile.TemporaryDirectory() as tmp:
        for seed in range(1, seeds + 1):
            path = os.path.join(tmp, "qmc_like.csv")
            simulate(path, seed, noise)
            cli = json.loads(subprocess.run([scalcal, "calibrate", "--measurements", path, "--rate", "50", "--magnitude",
                                             "auto", "--json"], capture_output=True, text=True).stdout)
            out = subprocess.run([host, path, "--rate", "50", "--magnitude", "auto", "--tumble"], capture_output=True,
                                 text=True).stdout
            lib = {l.split()[0]: l.split()[1:] for l in out.splitlines() if l.strip()}
            line = []
            for key, std in (("offset", "bias_std"), ("gain", "gain_std"), ("nonorthogonality", "nonorthogonality_std")):
                for k in range(3):
                    c = (cli[key][k] - truth[key][k]) / cli[std][k]
                    d = (float(lib[key][k]) - truth[key][k]) / cli[std][k]
                    zc.append(c), zd.append(d)
                    line.append("%s_%d %+.1f/%+.1f" % (key, k, c, d))
            print("seed %d (CLI/library, in the CLI's standard errors from the truth):" % seed, " ".join(line))
    rms = lambda v: math.sqrt(sum(x * x for x in v) / len(v))
    diff = [b - a for a, b in zip(zc, zd)]
    print("RMS from the truth: CLI %.2f, library %.2f; library - CLI: RMS %.2f, largest %.2f (the CLI's standard errors)"
          % (rms(zc), rms(zd), rms(diff), max(abs(x) for x in diff)))


if __name__ == "__main__":
    main()
