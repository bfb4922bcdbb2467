"""A log as it arrives: the rows of the public Xsens log handed to scalcal.PoseStream 100 at a time, as
a serial port would deliver them, the poses counted as they settle and the calibration fitted on
request, halfway and at the end (docs/python.md; run by ctest -L docs). Usage: pose_stream.py [LOG]"""
import os
import sys

import scalcal  # first: it pins OpenBLAS's kernel before numpy loads it
import numpy as np

here = os.path.dirname(os.path.abspath(__file__))
log = sys.argv[1] if len(sys.argv) > 1 else os.path.join(here, "..", "..", "data", "xsens_acc.txt")
rows = np.loadtxt(log)                                     # t, then the three raw outputs (counts)
stream = scalcal.PoseStream("xsens_acc.txt")
for k in range(0, len(rows), 100):
    chunk = rows[k:k + 100]
    stream.add(chunk[:, 0], chunk[:, 1:4], last=k + 100 >= len(rows))
    if k == 25000:                                         # halfway: what the poses so far give
        half = stream.calibrate(magnitude=9.81744, suggest=0)
        print(f"after {stream.state()['rows']} rows: {len(stream.poses())} poses, "
              f"bias_x {half['bias'][0]:.1f} +- {half['bias_std'][0]:.1f} counts")
cal = stream.calibrate(magnitude=9.81744, suggest=0)
print(f"after {stream.state()['rows']} rows in {stream.state()['chunks']} chunks: {len(stream.poses())} poses, "
      f"bias_x {cal['bias'][0]:.1f} +- {cal['bias_std'][0]:.1f} counts")
