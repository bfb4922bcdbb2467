#!/usr/bin/python3
# Writes example_bench.csv: an accelerometer triad on the 18-position program, 5 samples per
# position, g = 9.80665, with a 0.5 degree bench error. numpy only; independent of scalcal's code.
import numpy as np

rng = np.random.default_rng(2022)
g, sigma, tilt = 9.80665, 2e-3, np.radians(0.5)
bias = np.array([0.021, -0.013, 0.008])                  # m/s^2
dk = np.array([1.5e-3, -0.8e-3, 0.6e-3])
phi = np.array([[0, 4e-4, -6e-4], [2e-4, 0, 5e-4], [-3e-4, 1e-4, 0]])  # row k = sensor k's axis
Phi = phi + np.diag(np.sqrt(1 - (phi ** 2).sum(axis=1)))
A = np.diag(1 + dk) @ Phi
c = 1 / np.sqrt(2)
nominal = [v for a in range(3) for v in (np.eye(3)[a], -np.eye(3)[a])]
nominal += [s1 * c * np.eye(3)[a] + s2 * c * np.eye(3)[(a + 1) % 3]
            for a in range(3) for s1 in (1, -1) for s2 in (1, -1)]
print("# true: bias", bias, "dk", dk, "gamma xy,yz,zx",
      [phi[0, 1] + phi[1, 0], phi[1, 2] + phi[2, 1], phi[2, 0] + phi[0, 2]])
with open("example_bench.csv", "w") as f:
    f.write("# simulated by make_example_bench.py; bias %s m/s^2, dk %s, gamma %s rad\n" % (
        bias.tolist(), dk.tolist(), [phi[0, 1] + phi[1, 0], phi[1, 2] + phi[2, 1], phi[2, 0] + phi[0, 2]]))
    f.write("position,ix,iy,iz,x,y,z\n")
    for p, eta in enumerate(nominal, start=1):
        t = rng.normal(size=3)
        t -= t.dot(eta) * eta
        real = np.cos(tilt) * eta + np.sin(tilt) * t / np.linalg.norm(t)
        for _ in range(5):
            m = bias + A @ (g * real) + sigma * rng.normal(size=3)
            f.write("%d,%.6f,%.6f,%.6f,%.6f,%.6f,%.6f\n" % (p, *m, *eta))
