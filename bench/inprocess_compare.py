#!/usr/bin/env python3
"""In-process timings, interleaved: scalcal's bench_inprocess (one synthesize() call) against a peer's
optimisation time inside its own process (peers.py --workers 1 reports its starts' time without the
interpreter's start-up), the same number of starts and seed, one thread each, medians of the repeats.

usage: bench/inprocess_compare.py BUILD_DIR [--sizes 12,18,...] [--criteria D,A] [--starts 4] [--repeats 3]
Peers: L-BFGS-B on the unit vectors for D and A, a p-norm surrogate then SLSQP for E and S.
Prints one markdown row per criterion and N; a peer counts only if it reaches scalcal's value within 1e-6.
"""
import argparse, json, os, statistics, subprocess, sys

here = os.path.dirname(os.path.abspath(__file__))
PEER = {"D": "lbfgs", "A": "lbfgs", "E": "pnorm", "S": "pnorm"}


def run_json(cmd):
    out = subprocess.run(cmd, capture_output=True, text=True, check=True).stdout
    return json.loads(out.splitlines()[0])


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    ap.add_argument("build")
    ap.add_argument("--sizes", default="12,18,30,60,100,200,500,1000")
    ap.add_argument("--criteria", default="D,A")
    ap.add_argument("--starts", type=int, default=4)
    ap.add_argument("--repeats", type=int, default=3)
    a = ap.parse_args()
    bench = os.path.join(a.build, "bench", "bench_inprocess")
    print("| criterion, N | scalcal | peak | peer | ratio |\n| --- | --- | --- | --- | --- |")
    for c in a.criteria.split(","):
        for n in [int(s) for s in a.sizes.split(",")]:
            ours, theirs = [], []
            for _ in range(a.repeats):
                o = run_json([bench, "--positions", str(n), "--criterion", c, "--starts", str(a.starts), "--threads", "1"])
                p = run_json([sys.executable, os.path.join(here, "peers.py"), "--method", PEER[c], "--criterion", c,
                              "--positions", str(n), "--starts", str(a.starts), "--workers", "1"])
                ours.append(o["seconds"])
                theirs.append(p["seconds"])
            reached = p["value"] <= o["value"] * (1 + 1e-6)
            ms, mp = statistics.median(ours) * 1e3, statistics.median(theirs) * 1e3
            ratio = f"{mp / ms:.1f}x" if reached else f"peer misses ({p['value']:.8g})"
            print(f"| {c}, {n} | {ms:.2f} ms | {o['peak_mib']:.1f} MiB | {PEER[c]} {mp:.2f} ms | {ratio} |", flush=True)
    return 0


if __name__ == "__main__":
    sys.exit(main())
