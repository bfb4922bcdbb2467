#!/usr/bin/python3
"""How far scalcal's tumbling fit and a plain least-squares ellipsoid fit land from the truth at a cheap
magnetometer's noise (docs/magnetometer.md): 20 rehearsals (`scalcal simulate --tumble 300 --noise 0.056 --size
0.15`, the QMC5883L log's noise), each calibrated by `scalcal calibrate --magnitude auto` and by the
independent fit of real_data_fit.py (nonlinear least squares of |T (m - o)| - 1 over every sample); the offsets'
errors and scalcal's gains' in scalcal's standard errors. Usage: magnetometer_bias.py BUILD_DIR (Debian's python3, NumPy and SciPy).
"""
import json
import os
import subprocess
import sys
import tempfile

import numpy as np

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import real_data_fit  # noqa: E402

scalcal = os.path.join(sys.argv[1] if len(sys.argv) > 1 else "build", "experiments", "scalcal")
ours, theirs, gains = [], [], []
with tempfile.TemporaryDirectory() as work:
    log, truth = os.path.join(work, "log.csv"), os.path.join(work, "truth.json")
    for seed in range(1, 21):
        subprocess.run([scalcal, "simulate", "--tumble", "300", "--rate", "50", "--noise", "0.056", "--magnitude", "1",
                        "--size", "0.15", "--seed", str(seed), "--log", log, "--truth", truth],
                       check=True, capture_output=True)
        cal = json.loads(subprocess.run([scalcal, "calibrate", "--measurements", log, "--magnitude", "auto",
                                         "--suggest", "0", "--json"], check=True, capture_output=True,
                                        text=True).stdout)
        t = json.load(open(truth))
        x = np.loadtxt(log, delimiter=",", skiprows=2)[:, 1:]
        res, _ = real_data_fit.fit(x, 1.0, "paper9")
        o, _ = real_data_fit.unpack(res.x, "paper9")
        se = np.array(cal["bias_std"])
        ours += list((np.array(cal["offset"]) - t["offset"]) / se)
        theirs += list((o - t["offset"]) / se)
        # With --magnitude auto and a unit field the gains are 1 + the true scale deviations.
        gains += list((np.array(cal["gain"]) - 1 - np.array(t["scale_deviation"])) / np.array(cal["gain_std"]))
rms = lambda v: float(np.sqrt(np.mean(np.square(v))))  # noqa: E731
print(f"offsets' errors in scalcal's standard errors over 20 seeds: scalcal RMS {rms(ours):.2f}, "
      f"least squares RMS {rms(theirs):.2f}; scalcal's gains RMS {rms(gains):.2f}, largest {max(map(abs, gains)):.2f}")
