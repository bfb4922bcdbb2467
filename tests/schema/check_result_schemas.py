"""The JSON Schemas of the commands' `--json` results (docs/schema/results/) against what the commands print.

Runs a table of quick command lines (every variant of each result: the criteria D, A, E, S; the models paper9,
axis6, bias3, cubic12 and a thermal one; a region; Monte-Carlo and rehearsals; the export formats; the public
MPU-6050 log when ../shared/data is there) in a temporary folder, then checks, with python3-jsonschema as the
independent judge:
- every schema is a valid draft 2020-12 schema, and every output is valid by its command's schema;
- every key an output holds is declared (the schemas refuse undeclared keys), and every key a schema declares
  appears in some run's output, nested keys included: the schemas and the writers cannot drift apart unnoticed;
- the test can fail: outputs mutated (an extra key, a wrong type, a missing key, a bad enum value) are refused,
  and a schema with a key no writer prints is caught by the coverage check.
Usage: check_result_schemas.py SCALCAL SOURCE_DIR"""
import copy
import json
import os
import shlex
import subprocess
import sys
import tempfile
import time

import jsonschema

# Files the runs read, made first (their output is not checked): name, command line.
SETUP = [
    ("th.csv", "optimize --positions 18 --model paper9+T1 --temperature -10..50 --starts 2 --out th.csv"),
    ("thcap.csv", "optimize --positions 18 --model paper9+T1 --temperature -10..50 --region cap:90 --starts 2 "
                  "--out thcap.csv"),
    ("cap.csv", "optimize --positions 12 --region cap:90 --starts 2 --out cap.csv"),
    ("o9.csv", "optimize --positions 9 --starts 2 --out o9.csv"),
    ("o10.csv", "optimize --positions 10 --starts 4 --out o10.csv"),
    ("r1.jsonl", "sweep --positions 9..10 --criteria D --starts 2 --shard 0/2 --results r1.jsonl"),
    ("r2.jsonl", "sweep --positions 9..10 --criteria D --starts 2 --shard 1/2 --results r2.jsonl"),
    ("r3.jsonl", "sweep --positions 6 --criteria S --model axis6 --starts 2 --shard 0/1 --results r3.jsonl"),
    ("r4.jsonl", "sweep --positions 12 --criteria D --region cap:90 --starts 2 --shard 0/1 --results r4.jsonl"),
    ("cal.json", "calibrate --measurements data/xsens_acc.txt --magnitude 9.81744 --out cal.json"),
    ("calu.json", "calibrate --measurements data/xsens_acc.txt --magnitude 9.81744 --units m/s^2,m/s^2 "
                  "--out calu.json"),
]

# The runs: command line (--json added), expected exit code.
RUNS = [
    ("evaluate dodecahedral-12", 0), ("evaluate classic18 --model axis6", 0),
    ("evaluate classic18 --model bias3", 0), ("evaluate classic18 --model cubic12", 0),
    ("evaluate classic18 --instrument gyro", 0), ("evaluate cap.csv --region cap:90", 0),
    ("evaluate th.csv --model paper9+T1 --temperature -10..50", 0),
    ("evaluate thcap.csv --model paper9+T1 --temperature -10..50 --region cap:90", 0),
    ("catalogue", 0),
    ("limits", 0), ("limits --model axis6", 0), ("limits --model bias3", 0), ("limits --model cubic12", 0),
    ("limits --region cap:90", 0), ("limits --model paper9+T2 --temperature -10..50 --region cap:90", 0),
    ("optimize --positions 9 --starts 2", 0), ("optimize --positions 12 --criterion A --region cap:90 --starts 2", 0),
    ("optimize --positions 9 --model axis6 --starts 2", 0),
    ("optimize --positions 6 --model bias3 --criterion E --starts 2", 0),
    ("optimize --positions 12 --model cubic12 --criterion S --starts 2", 0),
    ("optimize --positions 9 --digits 20 --starts 2", 0),
    ("optimize --positions 12 --region cap:90 --margin 2 --starts 2", 0),
    ("optimize --positions 18 --model paper9+T1 --temperature -10..50 --region cap:90 --starts 2", 0),
    ("random --positions 9 --count 50", 0), ("random --positions 9 --count 50 --criterion A --model axis6", 0),
    ("random --positions 12 --count 50 --criterion E --region cap:90", 0),
    ("augment --program o9.csv --add 2 --starts 2", 0),
    ("augment --program o9.csv --add 1 --criterion A --model axis6 --starts 2", 0),
    ("augment --program cap.csv --add 1 --region cap:90 --criterion E --starts 2", 0),
    ("sweep --positions 9..10 --criteria D,A --starts 2", 0), ("sweep --positions 9 --criteria E --starts 2 "
                                                                "--no-timing", 0),
    ("sweep --positions 6 --criteria S --model axis6 --starts 2", 0),
    ("sweep --positions 12 --criteria D --region cap:90 --starts 2", 0),
    ("merge --results r1.jsonl --results r2.jsonl", 0), ("merge --results r1.jsonl --results r2.jsonl --no-timing", 0),
    ("merge --results r3.jsonl", 0), ("merge --results r4.jsonl", 0),
    ("certify dodecahedral-12 --criterion D", 0), ("certify table1-A --criterion A", 0),
    ("certify o10.csv --criterion D", 0),
    ("polish table1-A --criterion A --digits 20", 0), ("polish table3-S --criterion S --digits 20", 1),
    ("family dodecahedral", 0), ("family octahedral --param axes=a", 0),
    ("family rotation --param k=6 --model axis6", 0), ("family icosahedral --model cubic12", 0),
    ("family jig:dodecahedron", 0), ("family octahedral --model bias3", 0),
    ("jig dodecahedron --criterion A", 0), ("jig dodecahedron --instrument gyro", 0),
    ("jig cuboctahedron --starts 4 --criterion S", 0),
    ("plan dodecahedral-12 --bench gimbal:z,y,x", 0), ("plan rotation-4 --bench gimbal:z,y,x", 0),
    ("plan classic18 --bench tilt:90:flip", 0),
    ("plan classic18 --bench faces:45", 0), ("plan dodecahedral-12 --bench jig:dodecahedron", 0),
    ("plan dodecahedral-12 --bench rate:90:60:10:flip", 0), ("plan th.csv --bench gimbal:z,y,x --soak 30", 0),
    ("plan cap.csv --bench tilt:90 --region cap:90 --model axis6 --resolution 1", 0),
    ("plan dodecahedral-12 --bench gimbal:z,y,x --model cubic12", 0),
    ("simulate --program dodecahedral-12 --trials 20 --noise 0.01", 0),
    ("simulate --program classic18 --trials 20 --noise 0.01 --bench-error 0.5 --modulus projection --model axis6", 0),
    ("simulate --program classic18 --trials 20 --noise 0.01 --model cubic12", 0),
    ("simulate --program dodecahedral-12 --noise 0.01 --log sim.csv", 0),
    ("simulate --tumble 20 --rate 50 --noise 0.005 --magnitude 50 --size 0.1 --seed 3 --disturbances 2 "
     "--log mag.csv", 0),
    ("simulate --program dodecahedral-12 --model paper9+T2 --temperature -10..50 --ramp 2 --log ramp.csv "
     "--noise 1e-3 --size 3e-3 --seed 3 --rate 20", 0),
    ("simulate --instrument gyro --program dodecahedral-12 --magnitude 3.14159 --noise 1e-3 --dwell 10 "
     "--latitude 45 --log table.csv", 0),
    ("simulate --instrument gyro --program dodecahedral-12 --noise 1e-3 --turn-angle 360 --log turns.csv", 0),
    ("simulate --instrument gyro --program dodecahedral-12 --noise 1e-3 --accelerometer acc.csv --log hand.csv", 0),
    ("export cal.json --format json", 0), ("export cal.json --format imu_tk", 0),
    ("export cal.json --format magcal", 0), ("export cal.json --format c --name ACC", 0),
    ("export calu.json --format kalibr", 0), ("export calu.json --format px4 --force", 0),
    ("export calu.json --format ardupilot --instance 2 --force", 0),
]
SHARED_RUNS = [("export mpu6050.json --format imu_tk", 0)]


def resolve(schema, node, path):
    """A $ref followed: the target and its path, named after the definition (#name) so that a definition's keys
    count once however many places use it."""
    while isinstance(node, dict) and "$ref" in node:
        target = schema
        for part in node["$ref"].lstrip("#/").split("/"):
            target = target[part]
        node, path = target, "#" + node["$ref"].rsplit("/", 1)[-1]
    return node, path


def declared(schema, node, path, out, seen=None):
    """Every key path node declares (a.b[].c; a map's keys as *; a definition's keys under #name), into out."""
    seen = seen if seen is not None else set()
    node, path = resolve(schema, node, path)
    if not isinstance(node, dict) or (id(node), path) in seen:
        return
    seen.add((id(node), path))
    for key, sub in node.get("properties", {}).items():
        out.add(f"{path}.{key}")
        declared(schema, sub, f"{path}.{key}", out, seen)
    if isinstance(node.get("additionalProperties"), dict):
        out.add(f"{path}.*")
        declared(schema, node["additionalProperties"], f"{path}.*", out, seen)
    if isinstance(node.get("items"), dict):
        declared(schema, node["items"], f"{path}[]", out, seen)
    for key in ("allOf", "anyOf", "oneOf"):
        for sub in node.get(key, []):
            declared(schema, sub, path, out, seen)
    for key in ("then", "else"):
        if isinstance(node.get(key), dict):
            declared(schema, node[key], path, out, seen)


def applicable(schema, node, path, value):
    """The (subschema, path) pairs that apply to value: node, its allOf, the if's branch taken, the oneOf and
    anyOf members value is valid by; $refs followed."""
    node, path = resolve(schema, node, path)
    if not isinstance(node, dict):
        return []
    found = [(node, path)]

    def valid(sub):
        return jsonschema.Draft202012Validator({**sub, "$defs": schema.get("$defs", {})}).is_valid(value)
    for sub in node.get("allOf", []):
        found += applicable(schema, sub, path, value)
    for key in ("oneOf", "anyOf"):
        for sub in node.get(key, []):
            if valid(sub):
                found += applicable(schema, sub, path, value)
    if "if" in node:
        branch = node.get("then" if valid(node["if"]) else "else")
        if branch is not None:
            found += applicable(schema, branch, path, value)
    return found


def observed(schema, node, path, value, out):
    """Every key path value holds, named as declared() names them (the schema guides: a map's keys are *, a
    definition's keys #name); a key no applicable subschema declares is named as printed."""
    subs = applicable(schema, node, path, value)
    if isinstance(value, dict):
        for key, sub in value.items():
            child = next(((s["properties"][key], f"{p}.{key}") for s, p in subs if key in s.get("properties", {})),
                         None)
            if child is None:
                child = next(((s["additionalProperties"], f"{p}.*") for s, p in subs
                              if isinstance(s.get("additionalProperties"), dict)), (None, f"{path}.{key}"))
            out.add(child[1])
            if child[0] is not None:
                observed(schema, child[0], child[1], sub, out)
    elif isinstance(value, list):
        items = next(((s["items"], f"{p}[]") for s, p in subs if isinstance(s.get("items"), dict)), None)
        for sub in value:
            if items is not None:
                observed(schema, items[0], items[1], sub, out)


def run_all(scalcal, work, shared, failures):
    """Runs the setup and the table in work; returns {command: [outputs]}."""
    for name, command in SETUP:
        r = subprocess.run([scalcal, *shlex.split(command)], cwd=work, capture_output=True, text=True)
        if r.returncode != 0 or not os.path.exists(os.path.join(work, name)):
            failures.append(f"setup: scalcal {command}: exit {r.returncode}: {r.stderr.strip()[-300:]}")
    runs = list(RUNS)
    if shared:
        subprocess.run([scalcal, "calibrate", "--measurements", f"{shared}/mpu6050_acc.csv", "--rate", "100",
                        "--magnitude", "1", "--out", "mpu6050.json"], cwd=work,
                       capture_output=True)
        runs += SHARED_RUNS
    outputs = {}
    for command, expected in runs:
        r = subprocess.run([scalcal, *shlex.split(command), "--json"], cwd=work, capture_output=True, text=True)
        if r.returncode != expected:
            failures.append(f"scalcal {command} --json: exit {r.returncode} ({expected} expected): "
                            f"{r.stderr.strip()[-300:]}")
            continue
        try:
            document = json.loads(r.stdout)  # Python's reader takes NaN too: refused below
        except json.JSONDecodeError as e:
            failures.append(f"scalcal {command} --json: not JSON: {e}")
            continue
        if any(w in r.stdout for w in ("NaN", "Infinity")):
            failures.append(f"scalcal {command} --json: NaN or Infinity printed (not JSON)")
        outputs.setdefault(command.split()[0], []).append((command, document))
    return outputs, len(runs)


def check(schemas, outputs, failures):
    """Validates every output and checks the coverage both ways; returns the number of key paths checked."""
    checked = 0
    for name, schema in sorted(schemas.items()):
        validator = jsonschema.Draft202012Validator(schema)
        decl = set()
        declared(schema, schema, "$", decl)
        seen = set()
        for command, document in outputs.get(name, []):
            for e in validator.iter_errors(document):
                where = "/".join(map(str, e.absolute_path)) or "(top)"
                failures.append(f"{command}: {where}: {e.message[:200]}")
            observed(schema, schema, "$", document, seen)
        if name not in outputs:
            failures.append(f"{name}: no run prints this result")
            continue
        undeclared = sorted(seen - decl)
        if undeclared:
            failures.append(f"{name}: printed but not declared: {', '.join(undeclared)}")
        never = sorted(decl - seen)
        if never:
            failures.append(f"{name}: declared but printed by none of its {len(outputs[name])} runs: "
                            f"{', '.join(never)}")
        checked += len(decl)
    for name in sorted(set(outputs) - set(schemas)):
        failures.append(f"{name}: prints JSON but has no schema in docs/schema/results/")
    return checked


# Negative controls: (command, what, mutation); each mutated output must be refused by its schema.
MUTATIONS = [
    ("evaluate", "an extra key", lambda d: d.__setitem__("colour", 1)),
    ("evaluate", "D a string", lambda d: d.__setitem__("D", "1e7")),
    ("evaluate", "rank a float", lambda d: d.__setitem__("rank", 9.5)),
    ("evaluate", "no K", lambda d: d.pop("K")),
    ("evaluate", "a position of two numbers", lambda d: d["program"].__setitem__(0, [1.0, 0.0])),
    ("limits", "an extra key in D", lambda d: d["D"].__setitem__("note", "")),
    ("limits", "status 'maybe'", lambda d: d["D"].__setitem__("status", "maybe")),
    ("optimize", "positions a string", lambda d: d.__setitem__("positions", "9")),
    ("sweep", "an extra key in a row", lambda d: d[0].__setitem__("limits", None)),
    ("certify", "status unknown", lambda d: d.__setitem__("status", "proven")),
    ("catalogue", "an extra key in an evaluation", lambda d: d[0]["evaluation"].__setitem__("K", [])),
    ("plan", "a step without eta", lambda d: d["steps"][0].pop("eta")),
    ("simulate", "a Monte-Carlo result with a rehearsal's key", lambda d: d.__setitem__("rows", 5)),
    ("export", "a parameter that is a string", lambda d: d["parameters"].__setitem__("X", "1")),
]


def negative_controls(schemas, outputs, failures):
    """The schemas refuse mutated outputs, and the coverage check catches a key no writer prints."""
    done = 0
    for name, what, mutate in MUTATIONS:
        if name not in outputs:
            continue
        document = copy.deepcopy(outputs[name][0][1])
        mutate(document)
        if jsonschema.Draft202012Validator(schemas[name]).is_valid(document):
            failures.append(f"the {name} schema accepts an output with {what}")
        done += 1
    drifted = copy.deepcopy(schemas["random"])
    drifted["properties"]["criterion"] = {"type": "string", "description": "never printed"}
    caught = []
    check({"random": drifted}, {"random": outputs.get("random", [])}, caught)
    if not any("declared but printed by none" in c and "$.criterion" in c for c in caught):
        failures.append("the coverage check missed a declared key no run prints")
    loose = copy.deepcopy(schemas["random"])
    loose["additionalProperties"] = True
    loose["properties"].pop("seconds")
    caught = []
    check({"random": loose}, {"random": outputs.get("random", [])}, caught)
    if not any("printed but not declared" in c and "$.seconds" in c for c in caught):
        failures.append("the coverage check missed a printed key no schema declares")
    return done + 2


def complete(scalcal, source, schemas, outputs, failures):
    """Every command whose --help offers --json (the request schemas in docs/schema/ name every command) has a
    result schema and runs here; calibrate's are the calibration test's (check_calibration_schema.py)."""
    commands = [f[:-5] for f in os.listdir(os.path.join(source, "docs", "schema")) if f.endswith(".json")]
    for name in sorted(commands):
        r = subprocess.run([scalcal, name, "--help"], capture_output=True, text=True)
        if "--json" not in r.stdout or name == "calibrate":
            continue
        if name not in schemas:
            failures.append(f"{name} prints JSON (--json) but has no schema in docs/schema/results/")
        elif name not in outputs:
            failures.append(f"{name} has a result schema but no run in this test's table")


def main():
    """Loads the schemas, runs the table, checks; exit 1 on any failure."""
    start = time.monotonic()
    scalcal, source = os.path.abspath(sys.argv[1]), os.path.abspath(sys.argv[2])
    folder = os.path.join(source, "docs", "schema", "results")
    schemas = {}
    for f in sorted(os.listdir(folder)):
        # calibrate's result is the calibration file's keys: check_calibration_schema.py checks it with the file's.
        if f.endswith(".json") and f != "calibrate.json":
            schemas[f[:-5]] = json.load(open(os.path.join(folder, f)))
            jsonschema.Draft202012Validator.check_schema(schemas[f[:-5]])
    shared = os.path.join(os.path.dirname(source), "shared", "data")
    shared = shared if os.path.isdir(shared) else None
    failures = []
    with tempfile.TemporaryDirectory() as work:
        os.symlink(os.path.join(source, "data"), os.path.join(work, "data"))
        outputs, runs = run_all(scalcal, work, shared, failures)
    checked = check(schemas, outputs, failures)
    complete(scalcal, source, schemas, outputs, failures)
    controls = 0 if failures else negative_controls(schemas, outputs, failures)
    for f in failures:
        print(f, file=sys.stderr)
    if failures:
        sys.exit(1)
    print(f"result schemas: {len(schemas)} schemas, {runs} runs valid, {checked} key paths declared and all printed, "
          f"{controls} negative controls refused{'' if shared else ' (../shared/data absent: its runs skipped)'}; "
          f"{time.monotonic() - start:.1f} s")


if __name__ == "__main__":
    main()
