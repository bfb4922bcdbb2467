"""Runs every example of a Markdown page and compares what it prints with what the page shows.

An example is a line starting with "$ " inside a ```text or ```console block; the lines after it, up
to the next "$ " line or the end of the block, are what it prints (stdout and stderr as a terminal
shows them). In the expected text a line "..." stands for any number of lines, and "…" inside a line
for any text (a timing, a path); a number printed with a decimal point or an exponent matches within
one unit of its last printed digit (line_fits), so a value rounded the other way on another CPU still
matches, and nothing else does. Commands run in bash in a scratch folder that holds links to the
repository's data/ and experiments/ (and the public logs of ../shared/data as shared/), with the build's
`scalcal` first on PATH, so a page reads as a
user types. Usage: run_examples.py SOURCE_DIR BUILD_DIR PAGE.md... (exit 1 on the first mismatch
of each page, with both texts).
"""
import os
import re
from decimal import Decimal
import shutil
import subprocess
import sys
import tempfile


def examples(path):
    """(line number, command, expected lines) for every example of the page."""
    out, block, current = [], False, None
    with open(path, encoding="utf-8") as f:
        for number, line in enumerate(f, 1):
            line = line.rstrip("\n")
            if line.startswith("```"):
                if block and current:
                    out.append(current)
                block = line.strip() in ("```text", "```console") and not block
                current = None
                continue
            if not block:
                continue
            if line.startswith("$ "):
                if current:
                    out.append(current)
                current = (number, line[2:], [])
            elif current:
                current[2].append(line)
    return out


# A number as the pages print them: an optional sign, digits with a decimal point or an exponent
# (an integer is text: counts, line numbers and N compare exactly).
NUMBER = r"[-+]?(?:\d+\.\d*|\.\d+|\d+(?=[eE]))(?:[eE][-+]?\d+)?"


def last_digit_unit(text):
    """One unit in the last digit a number is printed with: 0.001 for 1.234, 100 for 1.70159e+07 (exact)."""
    mantissa, _, exponent = text.lower().partition("e")
    decimals = len(mantissa.split(".")[1]) if "." in mantissa else 0
    return Decimal(1).scaleb(int(exponent or 0) - decimals)


def line_fits(pattern, text):
    """Whether a line fits a page's line: text exactly, "…" any text, and each number printed with a
    decimal point or an exponent within one unit of its last printed digit (the last digit of a
    value may round either way on another CPU or BLAS kernel). A number followed by "…" is a prefix,
    as the page wrote it."""
    regex, numbers = "", []
    for k, part in enumerate(pattern.rstrip().split("…")):
        before_ellipsis = k < len(pattern.rstrip().split("…")) - 1
        pos = 0
        for m in re.finditer(NUMBER, part):
            if before_ellipsis and m.end() == len(part):
                break  # a prefix: compared as text
            regex += re.escape(part[pos:m.start()]) + "(" + NUMBER + ")"
            numbers.append(m.group(0))
            pos = m.end()
        regex += re.escape(part[pos:]) + (".*" if before_ellipsis else "")
    found = re.fullmatch(regex, text.rstrip())
    if not found:
        return False
    for want, got in zip(numbers, found.groups()):  # in decimal: the texts' own digits, exactly
        if abs(Decimal(want) - Decimal(got)) > last_digit_unit(want):
            return False
    return True


def matches(expected, actual):
    """True when the actual lines fit the expected ones ("..." lines, "…" inside lines)."""
    def fits(i, j):
        if i == len(expected):
            return j == len(actual)
        if expected[i].strip() == "...":
            return any(fits(i + 1, k) for k in range(j, len(actual) + 1))
        return j < len(actual) and line_fits(expected[i], actual[j]) and fits(i + 1, j + 1)

    return fits(0, 0)


def main(source, build, pages):
    work = tempfile.mkdtemp(prefix="scalcal_docs_")
    for name in ("data", "experiments", "python"):
        os.symlink(os.path.join(source, name), os.path.join(work, name))
    # The public logs beside the repository (../shared/data: the QMC5883L magnetometer, ...), as shared/.
    shared = os.path.join(os.path.dirname(os.path.abspath(source)), "shared", "data")
    if os.path.isdir(shared):
        os.symlink(shared, os.path.join(work, "shared"))
    env = dict(os.environ)
    env["PATH"] = os.path.join(build, "experiments") + os.pathsep + env.get("PATH", "")
    env["PYTHONPATH"] = os.path.join(build, "python")
    env["SCALCAL_DATA"] = os.path.join(source, "data")
    env["COLUMNS"] = "120"
    failed = 0
    try:
        for page in pages:
            for number, command, expected in examples(page):
                run = subprocess.run(["bash", "-c", command], cwd=work, env=env, stdout=subprocess.PIPE,
                                     stderr=subprocess.STDOUT, text=True, timeout=600)
                actual = run.stdout.rstrip("\n").split("\n") if run.stdout.strip() else []
                while expected and not expected[-1].strip():
                    expected = expected[:-1]
                if not matches(expected, actual):
                    failed += 1
                    print(f"{page}:{number}: $ {command}\n--- the page shows\n" + "\n".join(expected) +
                          "\n--- the command printed\n" + "\n".join(actual) + "\n")
                    break
    finally:
        shutil.rmtree(work, ignore_errors=True)
    print(f"{len(pages)} page(s), {failed} mismatch(es)")
    return 1 if failed else 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1], sys.argv[2], sys.argv[3:]))
