"""The bench path from Python, end to end: design a program for a tilt table, plan its settings,
rehearse the log a meter would write, calibrate it, save and reload the calibration, export it to
PX4 and apply it (docs/python.md; run by ctest -L docs). Usage: bench_path.py [FOLDER]"""
import json
import os
import sys

import numpy as np
import scalcal

folder = sys.argv[1] if len(sys.argv) > 1 else "."
path = lambda name: os.path.join(folder, name)  # noqa: E731

region = ["cap:40", "cap:40:0,0,-1"]                                                   # a tilt table, flipped too
design = scalcal.optimize(positions=18, criterion="D", region=region)
plan = scalcal.plan(design["program"], bench="tilt:40:flip", resolution=0.1, region=region)  # the settings
run = np.array([step["eta"] for step in plan["steps"]])                                # in the plan's order
truth = scalcal.simulate(program=run, noise=1e-3, magnitude=9.80665, seed=7,
                         log=path("log.csv"), truth=path("truth.json"))               # a rehearsal log
cal = scalcal.calibrate(measurements=path("log.csv"), magnitude=9.80665, suggest=0)    # a Calibration
cal.save(path("cal.json"))                                                             # what the CLI writes
again = scalcal.Calibration.load(path("cal.json"))
json.dumps(again)                                                                       # plain JSON values
px4 = scalcal.export(again, format="px4")                                              # PX4's parameters, m/s^2
rows = scalcal.correct(calibration=again, measurements=path("log.csv"))
print(f"design: D efficiency {design['efficiency']:.4f} on the two caps; plan: {len(plan['steps'])} steps, "
      f"{plan['remounts']} remount, {plan['total_travel_deg']:.1f} degrees of travel")
print(f"{cal['instrument']} calibration in {cal['units']['physical']}: bias_x {cal['bias'][0]:.5f} "
      f"+- {cal['bias_std'][0]:.5f} (truth {truth['bias'][0]:.5f})")
print("CAL_ACC0_XOFF", px4["parameters"]["CAL_ACC0_XOFF"])
print(f"corrected modulus: mean {np.mean(rows['modulus']):.5f}")
