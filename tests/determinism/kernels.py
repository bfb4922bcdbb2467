#!/usr/bin/python3
"""The same printed numbers under two OpenBLAS kernels (issue 49): every command below runs twice, with
OPENBLAS_CORETYPE set to each kernel, in a scratch folder of its own, and what it prints and every file it
writes must agree: text exactly; numbers printed with a decimal point or an exponent within one unit of
their last printed digit, or within 1e-6 of their size for numbers printed with 15 digits or more (an
optimum is converged to about 1e-8, Ipopt's tolerance, and where it is flat along a direction the positions
move further: S at N = 14 by 7e-8, and a region's symmetry about its axis; a program kept from another start
would differ by tenths); run
times (a number followed by " s", "seconds" keys) and "created" dates are left out. Decisions (which start
wins, which program is kept, a plan's order) show in every line, so they must be the same.
Usage: kernels.py SOURCE_DIR BUILD_DIR KERNEL_A KERNEL_B (exit 1 on the first difference of each command).
"""
import json
import os
import re
import shutil
import subprocess
import sys
import tempfile
from decimal import Decimal

NUMBER = r"[-+]?(?:\d+\.\d*|\.\d+|\d+(?=[eE]))(?:[eE][-+]?\d+)?"

# The bench workflow of docs/bench.md, design to export, the README's research examples, and the
# calibrations of the public logs (each its own step; files they write are compared too).
COMMANDS = [
    "scalcal optimize --positions 18 --criterion D --region cap:40 --region cap:40:0,0,-1 --out design.csv",
    "scalcal plan design.csv --bench tilt:40:flip --resolution 0.1 --out plan.csv",
    "scalcal simulate --program plan.csv --noise 1e-3 --magnitude 9.80665 --log log.csv --truth truth.json",
    "scalcal calibrate --measurements log.csv --magnitude 9.80665 --out cal.json",
    "scalcal export cal.json --format px4 --force",
    "scalcal optimize --positions 12 --criterion D --starts 4 --digits 45",
    "scalcal optimize --positions 18 --criterion A --seed 1 --out a18.csv",
    "scalcal optimize --positions 12 --criterion E --starts 8 --out e12.csv",
    "scalcal optimize --positions 14 --criterion S --starts 4 --out s14.csv",
    "scalcal limits --model axis6",
    "scalcal jig cuboctahedron --criterion A",
    "scalcal augment classic18 --add 2 --criterion D",
    "scalcal calibrate --measurements data/xsens_acc.txt --magnitude 9.81744 --suggest 2",
    "scalcal calibrate --measurements shared/qmc5883l_mag.csv --rate 50 --magnitude auto --suggest 1",
]


def unit(text):
    mantissa, _, exponent = text.lower().partition("e")
    decimals = len(mantissa.split(".")[1]) if "." in mantissa else 0
    return Decimal(1).scaleb(int(exponent or 0) - decimals)


def numbers_agree(a, b):
    x, y = Decimal(a), Decimal(b)  # the texts' own digits, exactly
    digits = len(re.sub(r"[^0-9]", "", a.lower().partition("e")[0]).lstrip("0"))
    tolerance = max(unit(a), unit(b))
    if digits >= 15:
        tolerance = max(tolerance, Decimal("1e-6") * max(Decimal(1), abs(x)))
    return abs(x - y) <= tolerance


def without_timings(line):
    line = re.sub(NUMBER + r" s\b", "<time> s", line)
    return re.sub(r'"(created|seconds)": [^,}]*', r'"\1": <left out>', line)


def lines_agree(a, b):
    a, b = without_timings(a), without_timings(b)
    pa, pb = re.split(NUMBER, a), re.split(NUMBER, b)
    na, nb = re.findall(NUMBER, a), re.findall(NUMBER, b)
    return pa == pb and len(na) == len(nb) and all(numbers_agree(x, y) for x, y in zip(na, nb))


def texts_agree(a, b):
    la, lb = a.splitlines(), b.splitlines()
    if len(la) != len(lb):
        return f"{len(la)} lines against {len(lb)}"
    for k, (x, y) in enumerate(zip(la, lb), 1):
        if not lines_agree(x, y):
            return f"line {k}:\n  {x}\n  {y}"
    return ""


def run(source, build, kernel, work):
    env = dict(os.environ, OPENBLAS_CORETYPE=kernel, PATH=os.path.join(build, "experiments") + os.pathsep +
               os.environ.get("PATH", ""), SCALCAL_DATA=os.path.join(source, "data"), COLUMNS="120")
    os.symlink(os.path.join(source, "data"), os.path.join(work, "data"))
    os.symlink(os.path.join(os.path.dirname(source), "shared", "data"), os.path.join(work, "shared"))
    out = []
    for command in COMMANDS:
        r = subprocess.run(["bash", "-c", command], cwd=work, env=env, stdout=subprocess.PIPE,
                           stderr=subprocess.STDOUT, text=True, timeout=600)
        out.append(f"[exit {r.returncode}]\n{r.stdout}")
    return out


def main(source, build, a, b):
    dirs = [tempfile.mkdtemp(prefix=f"scalcal_kernel_{k}_") for k in (a, b)]
    try:
        outputs = [run(source, build, k, d) for k, d in zip((a, b), dirs)]
        failed = 0
        for command, x, y in zip(COMMANDS, *outputs):
            why = texts_agree(x, y)
            if why:
                failed += 1
                print(f"{command}\n  differs under OPENBLAS_CORETYPE={a} and {b}: {why}")
        for name in sorted(os.listdir(dirs[0])):
            path = [os.path.join(d, name) for d in dirs]
            if os.path.islink(path[0]) or not os.path.isfile(path[0]):
                continue
            why = texts_agree(*(open(p, encoding="utf-8", errors="replace").read() for p in path))
            if why:
                failed += 1
                print(f"{name} differs under OPENBLAS_CORETYPE={a} and {b}: {why}")
        print(f"{len(COMMANDS)} commands under OPENBLAS_CORETYPE={a} and {b}: {failed} difference(s)")
        return 1 if failed else 0
    finally:
        for d in dirs:
            shutil.rmtree(d, ignore_errors=True)


if __name__ == "__main__":
    sys.exit(main(*sys.argv[1:5]))
