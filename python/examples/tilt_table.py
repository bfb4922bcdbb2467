# A calibration program for an accelerometer on a +-30 degree tilt table: gravity reaches the meter's
# frame only within 30 degrees of its +z axis (the region cap:30). Designs the D-optimal 18-position
# program there, compares it with the cap's certified limit, and plots it when matplotlib is installed.
# Usage: PYTHONPATH=build/python python3 python/examples/tilt_table.py [OUT.png]
import sys

import numpy as np

import scalcal

design = scalcal.optimize(positions=18, criterion="D", region="cap:30", seed=1)
limit = scalcal.limits(region="cap:30")["D"]
tilt = np.degrees(np.arccos(np.clip(design["program"][:, 2], -1, 1)))
azimuth = np.degrees(np.arctan2(design["program"][:, 1], design["program"][:, 0]))

print(f"D = {design['value']:.6g} on {design['region']}: efficiency {design['efficiency']:.4f} against the limit "
      f"{limit['value']:.6g} (proven >= {limit['lower_bound']:.6g})")
print("position  tilt_deg  azimuth_deg")
for k, (t, a) in enumerate(zip(tilt, azimuth), 1):
    print(f"{k:8d}  {t:8.3f}  {a:11.3f}")
quality = scalcal.evaluate(design["program"])
print("RMS errors per unit noise: theta_bias {:.4f}, theta_scale {:.4f}, theta_nonorth {:.4f}".format(
    quality["theta_bias"], quality["theta_scale"], quality["theta_nonorth"]))

try:
    import matplotlib

    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
except ImportError:
    print("matplotlib is not installed: no plot")
    sys.exit(0)
out = sys.argv[1] if len(sys.argv) > 1 else "tilt_table.png"
fig = plt.figure(figsize=(3.35, 3.35))  # 85 mm, one journal column
ax = fig.add_subplot(projection="polar")
ax.scatter(np.radians(azimuth), tilt, s=18, color="black")
ax.set_rmax(30)
ax.set_rticks([10, 20, 30])
ax.set_xlabel("azimuth; radius: tilt from +z (deg)", fontsize=8)
fig.tight_layout()
fig.savefig(out, dpi=300)
print("plot:", out)
