#!/usr/bin/python3
"""Same-run comparison of `scalcal optimize` with the NumPy/SciPy peers of bench/peers.py.

For each size N and criterion C, scalcal runs first and fixes the work: its start count (or
--peer-starts) is given to every peer that applies to C.  Each tool is timed as a whole process
(start-up included, as a user would meet it), the tools interleaved within each repeat so that load
from elsewhere on the machine falls on all of them alike; the median of the repeats is reported.
Peak memory is the child's ru_maxrss from os.wait4: for a multi-process child that is the largest
single process of its tree (a Pool of W workers holds about W times that), not their sum.

A tool "reaches" a value v when its own value <= v (1 + 1e-6).  ratio = seconds of the fastest peer
that reaches scalcal's value / scalcal's seconds.

usage: compare.py --scalcal PATH [--sizes 12,18,30,60,100,200] [--criteria D,A,E,S] [--repeats R]
                  [--workers W] [--seed S] [--peer-starts K] [--timeout SECONDS] [--out FILE.md]
The table goes to stdout (and --out); progress to stderr.
"""
import argparse
import json
import os
import signal
import statistics
import subprocess
import sys
import tempfile
import threading
import time

PEERS = ("lbfgs", "slsqp", "exchange")
PEERS_PY = os.path.join(os.path.dirname(os.path.abspath(__file__)), "peers.py")
REACH = 1e-6


def run(argv, timeout):
    """Run argv as its own session; return (exit code, stdout, stderr, wall s, peak MiB), exit code
    None on a timeout.  os.wait4 both reaps and gives the child's rusage; it blocks, so it runs in a
    thread and the clock stops the moment it returns, not at the next poll.  Linux counts this
    process's RSS at the spawn into the child's ru_maxrss (the pre-exec high-water mark is kept), so
    this process stays small (no numpy) and the table states that floor, measured on `true`."""
    with tempfile.TemporaryFile("w+") as out, tempfile.TemporaryFile("w+") as err:
        t0 = time.perf_counter()
        pid = os.posix_spawnp(argv[0], argv, os.environ, setsid=True,
                              file_actions=[(os.POSIX_SPAWN_DUP2, out.fileno(), 1),
                                            (os.POSIX_SPAWN_DUP2, err.fileno(), 2)])
        done = {}

        def reap():
            _, status, usage = os.wait4(pid, 0)
            done.update(seconds=time.perf_counter() - t0, status=status, usage=usage)

        waiter = threading.Thread(target=reap)
        waiter.start()
        waiter.join(timeout)
        timed_out = waiter.is_alive()
        if timed_out:  # the whole session: a peer's Pool workers die with it
            os.killpg(pid, signal.SIGKILL)
            waiter.join()
        out.seek(0)
        err.seek(0)
        code = None if timed_out else os.waitstatus_to_exitcode(done["status"])
        return code, out.read(), err.read(), done["seconds"], done["usage"].ru_maxrss / 1024


def check_same_criterion(got, criterion, log):
    """The peers' value of scalcal's own program must be scalcal's value, or the two sides would be
    optimising different things (a normalisation or row order slip).  In a child process: numpy in
    this one would raise every later child's ru_maxrss (see run)."""
    code = ("import json, sys, numpy; import peers; d = json.load(sys.stdin); "
            "print(peers.value(numpy.array(d['program']), d['criterion']))")
    mine = float(subprocess.run([sys.executable, "-c", code], input=json.dumps(got), text=True,
                                capture_output=True, cwd=os.path.dirname(PEERS_PY), check=True).stdout)
    if abs(mine - got["value"]) > 1e-9 * got["value"]:
        log(f"WARNING: N={got['positions']} {criterion}: peers.py values scalcal's program at {mine!r}, "
            f"scalcal at {got['value']!r}")


def fmt_value(v):
    return f"{v:.12g}"


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    ap.add_argument("--scalcal", required=True, help="path of the scalcal executable")
    ap.add_argument("--sizes", default="12,18,30,60,100,200")
    ap.add_argument("--criteria", default="D,A,E,S")
    ap.add_argument("--repeats", type=int, default=3)
    ap.add_argument("--workers", type=int, default=2,
                    help="peers' Pool processes and scalcal's --threads, so both use the same cores")
    ap.add_argument("--seed", type=int, default=1)
    ap.add_argument("--peer-starts", type=int, help="peers' start count (default: scalcal's)")
    ap.add_argument("--timeout", type=float, default=600, help="seconds per run")
    ap.add_argument("--out", help="also write the markdown table here")
    a = ap.parse_args()
    sizes = [int(s) for s in a.sizes.split(",")]
    criteria = a.criteria.split(",")
    common = ["--seed", str(a.seed)]

    def log(msg):
        print(msg, file=sys.stderr, flush=True)

    head = ["N", "criterion", "starts", "scalcal s", "scalcal value", "scalcal MiB"]
    for p in PEERS:
        head += [f"{p} s", f"{p} value", f"{p} MiB"]
    head += ["ratio", "note"]
    floor = run(["true"], a.timeout)[4]
    table = [f"scalcal optimize against bench/peers.py: {a.workers} worker(s) each (scalcal --threads), "
             f"median wall seconds of {a.repeats} repeat(s) of the whole process, seed {a.seed}, "
             f"timeout {a.timeout:g} s, {os.cpu_count()} cores; MiB = peak RSS of the largest process "
             f"(floor {floor:.0f} MiB: `true` measures that); "
             f"ratio = fastest peer reaching scalcal's value (within {REACH:g}) / scalcal.", "",
             "| " + " | ".join(head) + " |", "|" + "---|" * len(head)]

    for n in sizes:
        for c in criteria:
            argv = {"scalcal": [a.scalcal, "optimize", "--positions", str(n), "--criterion", c, "--json",
                                "--threads", str(a.workers)] + common}
            times = {}  # tool -> wall seconds of each repeat
            result = {}  # tool -> (value, MiB) of its first run, or a string: "n/a", "> timeout", "error"
            starts_cell = "-"
            for rep in range(a.repeats):
                for name in ("scalcal",) + PEERS:
                    if isinstance(result.get(name), str) or name not in argv:
                        continue  # n/a, timed out or failed (not run again), or scalcal failed
                    code, out, err, secs, mib = run(argv[name], a.timeout)
                    if code is None:
                        result[name] = f"> {a.timeout:g} s"
                    elif code == 2 and name != "scalcal":
                        result[name] = "n/a"
                    elif code != 0:
                        result[name] = "error"
                        log(f"N={n} {c} {name}: exit {code}: {err.strip()[-300:]}")
                    else:
                        got = json.loads(out)
                        times.setdefault(name, []).append(secs)
                        result.setdefault(name, (got["value"], mib))
                    if name == "scalcal" and rep == 0 and code == 0:  # its start count is the peers'
                        check_same_criterion(got, c, log)
                        starts = a.peer_starts or got["starts"]
                        starts_cell = f"{got['starts']}" + (f" (peers {starts})" if a.peer_starts else "")
                        for p in PEERS:
                            argv[p] = [sys.executable, PEERS_PY, "--method", p, "--criterion", c,
                                       "--positions", str(n), "--starts", str(starts),
                                       "--workers", str(a.workers)] + common
                    shown = result[name] if isinstance(result[name], str) else fmt_value(result[name][0])
                    log(f"N={n} {c} repeat {rep + 1}/{a.repeats} {name}: {secs:.3f} s {shown}")
            if isinstance(result.get("scalcal"), str):
                table.append(f"| {n} | {c} | - | {result['scalcal']} |" + " |" * (len(head) - 4))
                continue

            s_value, s_mib = result["scalcal"]
            s_secs = statistics.median(times["scalcal"])
            row = [str(n), c, starts_cell, f"{s_secs:.3f}", fmt_value(s_value), f"{s_mib:.0f}"]
            reaching, notes = [], []
            for p in PEERS:
                r = result.get(p, "n/a")
                if isinstance(r, str):
                    row += [r, "", ""]
                    continue
                secs = statistics.median(times[p])
                row += [f"{secs:.3f}", fmt_value(r[0]), f"{r[1]:.0f}"]
                if r[0] <= s_value * (1 + REACH):
                    reaching.append(secs)
                if s_value > r[0] * (1 + REACH):
                    notes.append(f"{p} lower than scalcal by {(s_value - r[0]) / s_value:.1e}")
            row += [f"{min(reaching) / s_secs:.3g}" if reaching else "-", "; ".join(notes)]
            table.append("| " + " | ".join(row) + " |")
    text = "\n".join(table) + "\n"
    sys.stdout.write(text)
    if a.out:
        with open(a.out, "w") as f:
            f.write(text)
    return 0


if __name__ == "__main__":
    sys.exit(main())
