"""The calibration file's JSON Schema (docs/schema/files/calibration_file.json) against the files calibrate writes,
and calibrate's --json result's (docs/schema/results/calibrate.json, the file's keys) against what it prints.

Writes calibration files of every kind the tool has (the paper's model, axis6, bias3 and cubic12; raw counts with
units and a sensor label; a log read in chunks; a simulated tumbling magnetometer; a thermal fit; a gyro on a rate
table, by known turns and by hand rotations against an accelerometer; the public MPU-6050 and QMC5883L logs when
../shared/data is there), then checks, with python3-jsonschema as the independent judge:
- the schemas are valid draft 2020-12 schemas, every file is valid by the file's, and what each run prints with
  --json by the result's, and is the file itself (the same document, header and units included, for every
  instrument, as Python's calibrate returns it);
- every key a file holds is declared (the schema refuses undeclared keys), and every declared key appears in
  some file: the schema and the writers cannot drift apart unnoticed;
- the reader agrees: a file the schema refuses for a wrong shape (offset of two numbers, a matrix row of two, a
  string in the matrix, format_version 3, no offset, a unit that is a number, an unknown instrument, 'linear'
  not a boolean or false under the paper's model) is refused by `scalcal correct --calibration` with exit 2, and the files as written are applied.
Usage: check_calibration_schema.py SCALCAL SOURCE_DIR"""
import copy
import json
import os
import subprocess
import sys
import tempfile

import jsonschema

scalcal, source = os.path.abspath(sys.argv[1]), os.path.abspath(sys.argv[2])
schema = json.load(open(os.path.join(source, "docs", "schema", "files", "calibration_file.json")))
jsonschema.Draft202012Validator.check_schema(schema)
validator = jsonschema.Draft202012Validator(schema)
result_schema = json.load(open(os.path.join(source, "docs", "schema", "results", "calibrate.json")))
jsonschema.Draft202012Validator.check_schema(result_schema)
# The result's $ref names the file's schema by its $id; the validator gets the file's schema embedded (under its own
# $id, so its "#" stays the file), so that no version of python3-jsonschema looks the $id up on the network.
assert result_schema["$ref"] == schema["$id"], result_schema["$ref"]
result_validator = jsonschema.Draft202012Validator({**result_schema, "$defs": {"calibration_file": schema}})
fields = schema["$defs"]["fields"]["properties"]
shared = os.path.join(os.path.dirname(os.path.abspath(source)), "shared", "data")
failures = []

RUNS = [
    ("paper9", "calibrate --measurements data/xsens_acc.txt --magnitude 9.81744"),
    ("axis6", "calibrate --measurements data/xsens_acc.txt --magnitude 9.81744 --model axis6"),
    ("bias3", "calibrate --measurements data/xsens_acc.txt --magnitude 9.81744 --model bias3"),
    ("units", "calibrate --measurements data/xsens_acc.txt --magnitude 9.81744 --units counts,m/s^2 --sensor Xsens"),
    ("stream", "calibrate --measurements data/xsens_acc.txt --magnitude auto --chunk 1000"),
    (None, "simulate --tumble 120 --rate 50 --noise 0.005 --magnitude 50 --size 0.1 --seed 3 --disturbances 2 "
           "--log mag.csv --truth mag_truth.json"),
    ("tumbling", "calibrate --measurements mag.csv --magnitude 50 --suggest 1"),
    ("cubic12", "calibrate --measurements mag.csv --magnitude 50 --model cubic12"),
    (None, "simulate --program dodecahedral-12 --model paper9+T2 --temperature -10..50 --ramp 2 --log ramp.csv "
           "--noise 1e-3 --size 3e-3 --seed 3 --rate 20"),
    ("thermal", "calibrate --measurements ramp.csv --model paper9+T2 --magnitude 1 --instrument accel "
                "--temperature -10..50"),
    (None, "simulate --instrument gyro --program dodecahedral-12 --magnitude 3.14159 --noise 1e-3 --dwell 10 "
           "--log table.csv --truth table_truth.json"),
    ("rate_table", "calibrate --instrument gyro --measurements table.csv --magnitude 3.14159 --units rad/s,rad/s"),
    (None, "simulate --instrument gyro --program dodecahedral-12 --noise 1e-3 --turn-angle 360 --log turns.csv "
           "--truth turns_truth.json"),
    ("known_turns", "calibrate --instrument gyro --measurements turns.csv --turn-angle 360"),
    ("hand_rotations", "calibrate --instrument gyro --measurements data/xsens_gyro.txt --accelerometer "
                       "data/xsens_acc.txt --accelerometer-magnitude 9.81744"),
]
if os.path.isdir(shared):
    RUNS += [("mpu6050", f"calibrate --measurements {shared}/mpu6050_acc.csv --rate 100 --magnitude auto"),
             ("qmc5883l", f"calibrate --measurements {shared}/qmc5883l_mag.csv --rate 50 --magnitude auto --suggest 1")]

MUTATIONS = {
    "offset of two numbers": lambda d: d.__setitem__("offset", d["offset"][:2]),
    "a matrix row of two": lambda d: d["matrix"].__setitem__(1, d["matrix"][1][:2]),
    "a string in the matrix": lambda d: d["matrix"][0].__setitem__(0, "1"),
    "format_version 3": lambda d: d.__setitem__("format_version", 3),
    "no offset": lambda d: d.pop("offset"),
    "a raw unit that is a number": lambda d: d["units"].__setitem__("raw", 5),
    "an unknown instrument": lambda d: d.__setitem__("instrument", "baro"),
    "'linear' not a boolean": lambda d: d.__setitem__("linear", "yes"),
    "'linear' false under the paper's model": lambda d: d.__setitem__("linear", False),
}


def undated(document):
    """A calibration document less its `created` keys, at any depth."""
    return {k: undated(v) if isinstance(v, dict) else v for k, v in document.items() if k != "created"}


with tempfile.TemporaryDirectory() as work:
    os.symlink(os.path.join(source, "data"), os.path.join(work, "data"))
    files, printed = {}, {}
    for name, command in RUNS:
        args = command.split()
        if name:
            args += ["--out", name + ".json"]
        r = subprocess.run([scalcal, *args], cwd=work, capture_output=True, text=True)
        if r.returncode != 0:
            failures.append(f"scalcal {command}: exit {r.returncode}: {r.stderr.strip()[-300:]}")
        elif name:
            files[name] = json.load(open(os.path.join(work, name + ".json")))
            r = subprocess.run([scalcal, *command.split(), "--json"], cwd=work, capture_output=True, text=True)
            printed[name] = json.loads(r.stdout) if r.returncode == 0 else None
    seen = set()
    for name, document in files.items():
        seen |= set(document)
        for e in validator.iter_errors(document):
            failures.append(f"{name}: {'/'.join(map(str, e.absolute_path)) or '(top)'}: {e.message[:200]}")
    for name, document in printed.items():
        if document is None:
            failures.append(f"{name}: calibrate --json failed")
            continue
        for e in result_validator.iter_errors(document):
            failures.append(f"{name} --json: {'/'.join(map(str, e.absolute_path)) or '(top)'}: {e.message[:200]}")
        # What --json prints is the file (`created` aside, a gyroscope's accelerometer's too: the two runs are a
        # moment apart).
        printed_doc, file_doc = undated(document), undated(files[name])
        differ = sorted(k for k in set(printed_doc) | set(file_doc) if printed_doc.get(k) != file_doc.get(k))
        if differ or "created" not in document:
            failures.append(f"{name} --json: differs from the file it writes in {differ}")
    if "paper9" in printed and printed["paper9"]:
        for what, mutate in [("no units", lambda d: d.pop("units")), ("a key 'colour'", lambda d: d.update(colour=1))]:
            document = copy.deepcopy(printed["paper9"])
            mutate(document)
            if result_validator.is_valid(document):
                failures.append(f"the result schema accepts an accelerometer's --json with {what}")
    never = sorted(set(fields) - seen)
    if never:
        failures.append(f"declared but written by none of the {len(files)} files: {', '.join(never)}")
    # The reader against the schema, on the paper's file as written and mutated.
    def correct(document):
        path = os.path.join(work, "mutated.json")
        json.dump(document, open(path, "w"))
        return subprocess.run([scalcal, "correct", "--calibration", path, "--measurements", "data/xsens_acc.txt",
                               "--out", os.path.join(work, "corrected.csv")], cwd=work, capture_output=True, text=True)
    if "paper9" in files:
        r = correct(files["paper9"])
        if r.returncode != 0:
            failures.append(f"correct refused the file calibrate wrote: {r.stderr.strip()}")
        for what, mutate in MUTATIONS.items():
            document = copy.deepcopy(files["paper9"])
            mutate(document)
            if validator.is_valid(document):
                failures.append(f"the schema accepts a file with {what}")
            r = correct(document)
            if r.returncode != 2 or r.stderr.count("\n") != 1:
                failures.append(f"correct on a file with {what}: exit {r.returncode} (2 and one line expected): "
                                f"{r.stderr.strip()[:200]}")

for f in failures:
    print(f, file=sys.stderr)
if failures:
    sys.exit(1)
print(f"calibration file schema: {len(files)} files of {len(RUNS) - sum(1 for n, _ in RUNS if not n)} kinds valid, "
      f"{len(fields)} keys declared and all written; calibrate --json valid on {len(printed)} runs, {len(MUTATIONS)} malformed files refused by both")
