"""A page's code excerpts against the files they quote: every ```cpp block whose first line is `// PATH` must
appear, as it stands below that line, in the file PATH of the source tree, so a worked example cannot go stale.
Fails too when the page quotes nothing (a test that checks nothing is no test).
Usage: check_excerpts.py SOURCE_DIR PAGE"""
import os
import re
import sys

source, page = sys.argv[1], sys.argv[2]
text = open(page).read()
blocks = re.findall(r"```cpp\n// ([^\n]+)\n(.*?)```", text, re.S)
failures = []
for path, body in blocks:
    full = os.path.join(source, path.strip())
    if not os.path.isfile(full):
        failures.append(f"{page}: quotes {path}, which is not a file")
    elif body not in open(full).read():
        failures.append(f"{page}: the excerpt of {path} beginning {body.splitlines()[0].strip()!r} is not in it")
if not blocks:
    failures.append(f"{page}: no ```cpp block opens with a // PATH line")
for f in failures:
    print(f, file=sys.stderr)
if failures:
    sys.exit(1)
print(f"{os.path.basename(page)}: {len(blocks)} excerpts, each in the file it names")
