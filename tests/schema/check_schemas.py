"""The JSON Schemas of the commands' requests (docs/schema/, `scalcal schema COMMAND`): every command has one,
docs/schema/ holds exactly the CLI's (scripts/make_schemas.sh writes them), each is a valid draft 2020-12 schema
by python3-jsonschema's own metaschema, and requests are judged alike by that independent validator and by
the CLI's `--request FILE`: those the schema accepts run and print what the same options on the command line
print; those it refuses (a wrong type, a value out of range, an unknown key, a required key missing) the CLI
refuses too, exit 2, naming the key. Usage: check_schemas.py SCALCAL SOURCE_DIR"""
import json
import os
import re
import subprocess
import sys
import tempfile

import jsonschema

scalcal, source = sys.argv[1], sys.argv[2]
failures = []


def run(*args):
    return subprocess.run([scalcal, *args], capture_output=True, text=True)


commands = re.findall(r"^  ([a-z]+)", run("help").stdout, re.M)
if len(commands) < 15:
    sys.exit(f"only {len(commands)} commands in `scalcal help`")
schemas = {}
for c in commands:
    r = run("schema", c)
    if r.returncode != 0:
        failures.append(f"schema {c}: exit {r.returncode}: {r.stderr.strip()}")
        continue
    schemas[c] = json.loads(r.stdout)
    path = os.path.join(source, "docs", "schema", c + ".json")
    if not os.path.exists(path) or open(path).read() != r.stdout:
        failures.append(f"docs/schema/{c}.json is not `scalcal schema {c}` (scripts/make_schemas.sh writes it)")
    try:
        jsonschema.Draft202012Validator.check_schema(schemas[c])
    except jsonschema.SchemaError as e:
        failures.append(f"schema {c} is not a valid draft 2020-12 schema: {e.message}")
# A build without plots (SCALCAL_BUILD_PLOTS=OFF) has no `plot` and `reproduce`; their schemas stay published.
extra = sorted(set(f[:-5] for f in os.listdir(os.path.join(source, "docs", "schema")) if f.endswith(".json")) - set(commands)
               - {"plot", "reproduce"})
if extra:
    failures.append(f"docs/schema/ has schemas of no command: {extra}")

# (command, request, the same on the command line, or for a request the schema refuses the key the CLI
# must name)
CASES = [
    ("evaluate", {"program": "classic18", "model": "axis6"}, ["classic18", "--model", "axis6"]),
    ("evaluate", {"program": "classic18", "region": ["band:0:180"], "tolerance": 0.5},
     ["classic18", "--region", "band:0:180", "--tolerance", "0.5"]),
    ("limits", {"region": ["cap:90"], "model": "paper9"}, ["--region", "cap:90", "--model", "paper9"]),
    ("random", {"positions": 12, "count": 500, "seed": 7, "criterion": "A"},
     ["--positions", "12", "--count", "500", "--seed", "7", "--criterion", "A"]),
    ("optimize", {"positions": 2}, "positions"),                       # below the minimum
    ("optimize", {"positions": 12.5}, "positions"),                    # not an integer
    ("evaluate", {"program": "classic18", "colour": "red"}, "colour"),  # no such field
    ("evaluate", {"model": "paper9"}, "program"),                      # the required program missing
    ("evaluate", {"program": ["classic18"]}, "program"),               # neither a name nor positions
    ("evaluate", {"program": "classic18", "region": "cap:90"}, "region"),  # a repeated option needs an array
]


def without_seconds(j):
    if isinstance(j, dict):
        return {k: without_seconds(v) for k, v in j.items() if k != "seconds"}
    if isinstance(j, list):
        return [without_seconds(v) for v in j]
    return j


with tempfile.TemporaryDirectory() as work:
    for i, (c, request, line) in enumerate(CASES):
        valid = not list(jsonschema.Draft202012Validator(schemas[c]).iter_errors(request))
        accepted = isinstance(line, list)
        if valid != accepted:
            failures.append(f"{c} {request}: the schema {'accepts' if valid else 'refuses'} it, the case says otherwise")
            continue
        path = os.path.join(work, f"request{i}.json")
        with open(path, "w") as f:
            json.dump(request, f)
        got = run(c, "--request", path, "--json")
        if not accepted:
            if got.returncode != 2 or f"'{line}'" not in got.stderr or len(got.stderr.strip().splitlines()) != 1:
                failures.append(f"{c} {request}: refused by the schema, but the CLI gave exit {got.returncode} "
                                f"without naming '{line}' in one line: {got.stderr.strip()}")
            continue
        want = run(c, *line, "--json")
        if got.returncode != 0 or want.returncode != 0 or \
                without_seconds(json.loads(got.stdout)) != without_seconds(json.loads(want.stdout)):
            failures.append(f"{c} {request}: exit {got.returncode} ({got.stderr.strip()}), and the output differs "
                            f"from `scalcal {c} {' '.join(line)} --json`")
    # A program given as positions: the same criteria as the same positions in a CSV file.
    positions = [[1, 0, 0], [0, 1, 0], [0, 0, 1], [-1, 0, 0], [0, -1, 0], [0, 0, -1], [0.6, 0.8, 0], [0, 0.6, 0.8],
                 [0.8, 0, 0.6], [-0.6, 0.8, 0], [0, -0.6, 0.8], [0.8, 0, -0.6]]
    with open(os.path.join(work, "p.csv"), "w") as f:
        f.write("x,y,z\n" + "".join(f"{x},{y},{z}\n" for x, y, z in positions))
    with open(os.path.join(work, "p.json"), "w") as f:
        json.dump({"program": positions}, f)
    a = json.loads(run("evaluate", "--request", os.path.join(work, "p.json"), "--json").stdout)
    b = json.loads(run("evaluate", os.path.join(work, "p.csv"), "--json").stdout)
    if a.get("criteria") != b.get("criteria"):
        failures.append(f"a program given as positions: criteria {a.get('criteria')} against the file's {b.get('criteria')}")

for f in failures:
    print("check_schemas:", f, file=sys.stderr)
if failures:
    sys.exit(1)
print(f"{len(schemas)} commands' request schemas: as docs/schema/ has them, valid draft 2020-12; "
      f"{len(CASES) + 1} requests judged alike by jsonschema and the CLI")
