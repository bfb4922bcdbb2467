# The Python module against the CLI: every binding is called on the same inputs as `scalcal ... --json`
# and must return the same object (NumPy arrays compared as lists, bit for bit: both run the same C++).
# The run time (`seconds`) is the only key left out. Errors must carry the CLI's message.
# Run by ctest (python.bindings) with PYTHONPATH at the built module and SCALCAL_CLI at the executable.
import json
import math
import os
import re
import subprocess
import sys

import numpy as np
import pytest

import scalcal

CLI = os.environ["SCALCAL_CLI"]
DATA = os.path.join(os.environ["SCALCAL_SOURCE_DIR"], "data")


def cli(*args, expect=0):
    r = subprocess.run([CLI, *args], capture_output=True, text=True)
    assert r.returncode == expect, r.stderr
    return r


def cli_json(*args, expect=0):
    return json.loads(cli(*args, "--json", expect=expect).stdout)


# How each front end names an option in a sentence (numeric/io/option_words.hpp): the shell's "--magnitude 9.81"
# or "--still," and Python's "magnitude=9.81" or "still=,". The same fact reads alike once both are one token.
OPTION_WORD = re.compile(r"(?<![\w-])(--[a-z][a-z0-9-]*|[a-z][a-z0-9_]*=) ?")


def plain(value):
    """The module's result as the JSON reader gives the CLI's: arrays as lists, NaN as None, options named in
    one way (OPTION_WORD)."""
    if isinstance(value, str):
        return OPTION_WORD.sub("OPTION ", value)
    if isinstance(value, np.ndarray):
        return plain(value.tolist())
    if isinstance(value, dict):
        return {k: plain(v) for k, v in value.items()}
    if isinstance(value, list):
        return [plain(v) for v in value]
    if isinstance(value, float) and not math.isfinite(value):
        return None
    return value


def same(py_result, cli_result, ignore=("seconds",)):
    got = {k: v for k, v in plain(py_result).items() if k not in ignore}
    want = {k: v for k, v in plain(cli_result).items() if k not in ignore}
    assert list(got) == list(want)  # the same keys in the same order
    for k in want:
        assert got[k] == want[k], k


def cli_calibration(tmp_path, *args):
    """The calibration file the CLI writes (calibrate ... --out), which Python's calibrate returns."""
    out = tmp_path / "cli_cal.json"
    cli("calibrate", *args, "--out", str(out))
    with open(out) as f:
        return json.load(f)


def write_program(path, positions):
    with open(path, "w") as f:
        f.write("x,y,z\n")
        for p in positions:
            f.write(",".join(repr(float(c)) for c in p) + "\n")


def random_program(n, seed):
    v = np.random.default_rng(seed).normal(size=(n, 3))
    return v / np.linalg.norm(v, axis=1, keepdims=True)


def test_evaluate_catalogue_name():
    r = scalcal.evaluate("octahedral-1-1-0")
    same(r, cli_json("evaluate", "octahedral-1-1-0"))
    assert isinstance(r["K"], np.ndarray) and r["K"].shape == (9, 9)
    assert r["program"].shape == (18, 3)


def test_evaluate_array_equals_file(tmp_path):
    positions = random_program(14, seed=5)
    path = tmp_path / "p.csv"
    write_program(path, positions)
    same(scalcal.evaluate(positions), cli_json("evaluate", str(path)))
    same(scalcal.evaluate(positions, model="cubic12"), cli_json("evaluate", str(path), "--model", "cubic12"))


def test_evaluate_on_a_region(tmp_path):
    # Within 60 degrees of +z: the efficiency against the cap's limits is the CLI's.
    positions = random_program(16, seed=2)
    positions[:, 2] = np.abs(positions[:, 2]) + 1.0
    positions /= np.linalg.norm(positions, axis=1, keepdims=True)
    path = tmp_path / "cap.csv"
    write_program(path, positions)
    r = scalcal.evaluate(positions, region="cap:60")
    same(r, cli_json("evaluate", str(path), "--region", "cap:60"))
    assert set(r["efficiency"]) == {"D", "A", "E", "S"}


def test_optimize():
    args = dict(starts=6, seed=3, threads=1)
    r = scalcal.optimize(positions=12, criterion="A", **args)
    same(r, cli_json("optimize", "--positions", "12", "--criterion", "A", "--starts", "6", "--seed", "3",
                     "--threads", "1"))
    assert r["program"].shape == (12, 3)
    same(scalcal.optimize(positions=8, criterion="D", model="axis6", **args),
         cli_json("optimize", "--positions", "8", "--criterion", "D", "--model", "axis6", "--starts", "6",
                  "--seed", "3", "--threads", "1"))


def test_optimize_on_a_region():
    r = scalcal.optimize(positions=12, criterion="D", region=["cap:45", "cap:45:0,0,-1"], starts=2, seed=1, threads=1)
    same(r, cli_json("optimize", "--positions", "12", "--criterion", "D", "--region", "cap:45",
                     "--region", "cap:45:0,0,-1", "--starts", "2", "--seed", "1", "--threads", "1"))


def test_limits():
    same(scalcal.limits(), cli_json("limits"))
    same(scalcal.limits(model="bias3"), cli_json("limits", "--model", "bias3"))
    assert scalcal.limits()["D"]["exact"] == "61509375/4"
    assert scalcal.limits()["D"]["theorem"] == "proofs/d_limit.md"
    # On the hemisphere the theorems' closed forms come through with their status (A is certified).
    cap = scalcal.limits(region="cap:90")
    same(cap, cli_json("limits", "--region", "cap:90"))
    assert (cap["E"]["exact"], cap["E"]["theorem"], cap["E"]["status"]) == ("147", "proofs/cap_es_limits.md", "proven")
    assert (cap["S"]["exact"], cap["A"]["status"]) == ("81", "certified")


def simulated_bench(seed):
    """A meter with a bias, scale errors and non-orthogonality on the 18-position octahedral program,
    five noisy samples per position (position labels 1..18), in units where |I| = 9.81."""
    rng = np.random.default_rng(seed)
    eta = scalcal.program("octahedral-1-1-0")
    gain = np.array([[1.01, 0.002, -0.001], [0.0, 0.995, 0.003], [0.0, 0.0, 1.004]])
    samples, labels = [], []
    for k, e in enumerate(eta):
        for _ in range(5):
            samples.append(gain @ (9.81 * e) + [0.05, -0.02, 0.03] + rng.normal(scale=0.002, size=3))
            labels.append(k + 1)
    return np.array(samples), np.array(labels), np.repeat(eta, 5, axis=0)


def test_calibrate_grouped_samples(tmp_path):
    samples, labels, nominal = simulated_bench(seed=7)
    path = tmp_path / "bench.csv"
    with open(path, "w") as f:
        f.write("ix,iy,iz,position,x,y,z\n")
        for s, p, n in zip(samples, labels, nominal):
            f.write(",".join(repr(float(v)) for v in (*s, p, *n)) + "\n")
    columns = {"ix": samples[:, 0], "iy": samples[:, 1], "iz": samples[:, 2], "position": labels}
    with_nominal = dict(columns, x=nominal[:, 0], y=nominal[:, 1], z=nominal[:, 2])
    # Python's calibrate returns the calibration file's object (what --out writes), a Calibration;
    # its run time is the file's "created".
    skip = ("seconds", "created")
    r = scalcal.calibrate(measurements=columns, magnitude=9.81)
    same(r, cli_calibration(tmp_path, "--measurements", str(path), "--magnitude", "9.81"), skip)
    assert len(r["excluded_samples"]) == 0 and r["converged"]
    assert isinstance(r, scalcal.Calibration) and json.loads(json.dumps(r)) == r
    same(scalcal.calibrate(measurements=path, magnitude="auto"),
         cli_calibration(tmp_path, "--measurements", str(path), "--magnitude", "auto"), skip)
    same(scalcal.calibrate(measurements=with_nominal, magnitude=9.81, modulus="projection", suggest=1),
         cli_calibration(tmp_path, "--measurements", str(path), "--magnitude", "9.81", "--modulus", "projection",
                         "--suggest", "1"), skip)
    same(scalcal.calibrate(measurements=columns, magnitude=9.81, model="axis6"),
         cli_calibration(tmp_path, "--measurements", str(path), "--magnitude", "9.81", "--model", "axis6"), skip)
    # Nominal directions longer than the samples (issue 36): refused, naming the column, not truncated.
    longer = dict(columns, x=np.append(nominal[:, 0], 1.0), y=nominal[:, 1], z=nominal[:, 2])
    with pytest.raises(ValueError, match=r"measurements\[x\] must have shape \(%d,\)" % len(labels)):
        scalcal.calibrate(measurements=longer, magnitude=9.81, modulus="projection")


def test_calibrate_raw_log(tmp_path):
    # The real log of docs/calibrate.md, read by NumPy: a text log has no header, so its lines are the rows.
    path = os.path.join(DATA, "xsens_acc.txt")
    log = np.loadtxt(path)
    r = scalcal.calibrate(measurements={"t": log[:, 0], "ix": log[:, 1], "iy": log[:, 2], "iz": log[:, 3]},
                          magnitude=9.81744)
    same(r, cli_calibration(tmp_path, "--measurements", path, "--magnitude", "9.81744"), ("seconds", "created"))
    assert len(r["intervals"]) >= 9


def test_simulate_gyro(tmp_path):
    # simulate --instrument gyro: known turns, and hand rotations with the accelerometer's log; the same
    # files as the CLI's and its --json (the truth).
    for method in (["--turn-angle", "360"], ["--accelerometer"]):
        files = {}
        for who in ("py", "cli"):
            files[who] = [tmp_path / f"{who}_{name}" for name in ("log.csv", "truth.json", "acc.csv")]
        args = ["--instrument", "gyro", "--program", "dodecahedral-12", "--noise", "1e-3", "--dwell", "2"]
        cli_args = args + method + ([str(files["cli"][2])] if method == ["--accelerometer"] else [])
        want = cli_json("simulate", *cli_args, "--log", str(files["cli"][0]), "--truth", str(files["cli"][1]))
        kw = {"turn_angle": 360} if method[0] == "--turn-angle" else {"accelerometer": str(files["py"][2])}
        got = scalcal.simulate(instrument="gyro", program="dodecahedral-12", noise=1e-3, dwell=2,
                               log=str(files["py"][0]), truth=str(files["py"][1]), **kw)
        same(got, want)
        assert json.loads(files["py"][1].read_text()) == json.loads(files["cli"][1].read_text())
        for k in (0, 2) if method == ["--accelerometer"] else (0,):  # the logs, to the byte
            assert files["py"][k].read_bytes() == files["cli"][k].read_bytes(), files["py"][k].name


def test_calibrate_gyro(tmp_path):
    # calibrate --instrument gyro: a rate-table rehearsal and IMU-TK's Xsens pair (hand rotations), the
    # file's object as the CLI writes it.
    log = tmp_path / "table.csv"
    cli("simulate", "--instrument", "gyro", "--program", "dodecahedral-12", "--magnitude", "3.14159", "--noise",
        "1e-3", "--dwell", "4", "--log", str(log))
    skip = ("seconds", "created")
    r = scalcal.calibrate(instrument="gyro", measurements=str(log), magnitude=3.14159)
    same(r, cli_calibration(tmp_path, "--instrument", "gyro", "--measurements", str(log), "--magnitude", "3.14159"),
         skip)
    assert r["instrument"] == "gyro" and r["method"] == "rate_table" and len(r["segments"]) == 12
    gyro, acc = os.path.join(DATA, "xsens_gyro.txt"), os.path.join(DATA, "xsens_acc.txt")
    r = scalcal.calibrate(instrument="gyro", measurements=gyro, accelerometer=acc, accelerometer_magnitude=9.81744)
    want = cli_calibration(tmp_path, "--instrument", "gyro", "--measurements", gyro, "--accelerometer", acc,
                           "--accelerometer-magnitude", "9.81744")

    def undated(c):  # the accelerometer's calibration beside the gyro's has its own run time
        return dict(c, accelerometer={k: v for k, v in c["accelerometer"].items() if k != "created"})

    same(undated(r), undated(want), skip)
    assert r["method"] == "hand_rotations" and r["accelerometer"]["instrument"] == "accel"


def test_errors_carry_the_cli_message(tmp_path):
    planar = random_program(12, seed=1)
    planar[:, 2] = 0
    planar /= np.linalg.norm(planar, axis=1, keepdims=True)
    path = tmp_path / "planar.csv"
    write_program(path, planar)
    with pytest.raises(scalcal.InputError) as e:
        scalcal.evaluate(planar)
    message = cli("evaluate", str(path), expect=2).stderr.strip()
    assert message == f"scalcal evaluate: {path}: " + str(e.value).split(": ", 1)[1]

    bad = random_program(10, seed=1)
    bad[1, 1] = np.nan
    with pytest.raises(scalcal.InputError, match=r"^program:2: value in column y is not finite"):
        scalcal.evaluate(bad)
    with pytest.raises(ValueError, match=r"program must have shape \(M, 3\), got \(10, 2\)"):
        scalcal.evaluate(bad[:, :2])
    with pytest.raises(scalcal.UsageError, match="criterion: must be D, A, E or S, got 'Q'"):
        scalcal.optimize(positions=12, criterion="Q")
    with pytest.raises(scalcal.UsageError) as e:
        scalcal.optimize(positions=5, criterion="D")
    assert "positions=5 is below the 9 parameters of model=paper9" in str(e.value)  # in Python's words
    assert "--positions 5 is below the 9 parameters" in cli("optimize", "--positions", "5", expect=2).stderr
    with pytest.raises(scalcal.InputError) as e:
        scalcal.limits(region="cap:500")
    message = cli("limits", "--region", "cap:500", expect=2).stderr
    assert str(e.value).startswith("region: ") and "--region: " + str(e.value)[len("region: "):] in message


def test_same_seed_same_program():
    a = scalcal.optimize(positions=10, criterion="E", starts=3, seed=11, threads=2)
    b = scalcal.optimize(positions=10, criterion="E", starts=3, seed=11, threads=1)
    assert np.array_equal(a["program"], b["program"]) and a["value"] == b["value"]


def test_export_is_the_cli_export(tmp_path):
    # A calibration file written by the CLI, exported by both to PX4's parameters and imu_tk's text.
    cal = tmp_path / "cal.json"
    cli("calibrate", "--measurements", os.path.join(DATA, "xsens_acc.txt"), "--magnitude", "9.81744", "--out", str(cal))
    # The log is in counts: PX4 needs the driver's scale (about 1/413.7 m/s^2 per count here); the Xsens
    # triad's non-orthogonality (0.021 rad between y and z) is more than PX4's diagonal scales carry (1.2 %
    # of a corrected vector): force writes them, with a warning.
    r = scalcal.export(str(cal), format="px4", raw_scale="0.0024171m/s^2", force=True)
    same(r, cli_json("export", str(cal), "--format", "px4", "--raw-scale", "0.0024171m/s^2", "--force"))
    assert r["text"] and 0.01 < r["dropped_relative"] < 0.013
    same(scalcal.export(str(cal), format="imu_tk"), cli_json("export", str(cal), "--format", "imu_tk"))
    # The dict calibrate() returns exports as its file does (issue 49).
    c = scalcal.calibrate(measurements=os.path.join(DATA, "xsens_acc.txt"), magnitude=9.81744)
    assert scalcal.export(c, format="imu_tk")["text"] == scalcal.export(str(cal), format="imu_tk")["text"]


def test_stubs_state_what_the_functions_take():
    # The stubs come from the option tables: a flag's default is a bool, a quantity takes a number, a
    # path a PathLike (issue 33), and every stub is valid Python.
    stubs = open(os.path.join(os.path.dirname(scalcal.__file__), "__init__.pyi")).read()
    compile(stubs, "__init__.pyi", "exec")
    assert "keep_outliers: bool | None = False" in stubs
    assert "quick: bool | None = False" in stubs
    assert "magnitude: str | float" in stubs
    assert "measurements: str | os.PathLike[str]" in stubs
    assert "= '0'" not in stubs


@pytest.mark.parametrize("model, positions", [("paper9+bias:T3", "48"), ("bias3+T3", "24")])
def test_thermal_workflow_is_the_cli_s(tmp_path, model, positions):
    # Issue 53 end to end in both front ends: the product program, its plan with soaks, a rehearsal, the thermal
    # calibration, its correction at each row's temperature and the autopilots' thermal parameters; over the paper's
    # meter and the offsets-only base.
    program = tmp_path / "thermal.csv"
    cli("optimize", "--model", model, "--temperature", "-20..60", "--criterion", "D", "--positions", positions,
        "--seed", "1", "--out", str(program))
    same(scalcal.plan(program=str(program), bench="gimbal:x,y", soak=20),
         cli_json("plan", str(program), "--bench", "gimbal:x,y", "--soak", "20"))
    log = tmp_path / "oven.csv"
    cli("simulate", "--program", str(program), "--model", model, "--temperature", "-20..60", "--log", str(log),
        "--noise", "1e-3", "--size", "3e-3", "--seed", "7", "--rate", "50")
    args = ("--measurements", str(log), "--model", model, "--magnitude", "1", "--instrument", "accel",
            "--temperature", "-20..60")
    cal = cli_calibration(tmp_path, *args)
    c = scalcal.calibrate(measurements=str(log), model=model, magnitude=1, instrument="accel",
                          temperature="-20..60")
    assert plain(c)["parameters"] == cal["parameters"]
    cal_path = tmp_path / "cli_cal.json"
    same(scalcal.correct(calibration=str(cal_path), measurements=str(log)),
         cli_json_correct(cal_path, log))
    for fmt in ("px4", "ardupilot"):
        same(scalcal.export(str(cal_path), format=fmt), cli_json("export", str(cal_path), "--format", fmt))


def cli_json_correct(cal, log):
    """correct has no --json: its CSV read back as the module's columns."""
    lines = cli("correct", "--calibration", str(cal), "--measurements", str(log)).stdout.splitlines()
    head = lines[0].split(",")
    cols = {h: [] for h in head}
    for line in lines[1:]:
        for h, v in zip(head, line.split(",")):
            cols[h].append(float(v))
    return cols


def test_sweep_through_a_map_is_one_sweep():
    # sweep(map=...) runs each (criterion, N) task as a shard of its own through the caller's map (issue 51):
    # builtins.map and a process pool give the rows one call gives, and one process's shards the CLI's.
    from concurrent.futures import ProcessPoolExecutor
    kw = dict(positions="9..12", criteria="D,A", starts=3, seed=4, threads=1)
    one = plain(scalcal.sweep(**kw))
    assert len(one) == 8
    drop = lambda rows: [{k: v for k, v in r.items() if k != "seconds"} for r in rows]  # noqa: E731
    assert drop(plain(scalcal.sweep(**kw, map=map))) == drop(one)
    with ProcessPoolExecutor(2) as pool:
        assert drop(plain(scalcal.sweep(**kw, map=pool.map))) == drop(one)
    # A shard is the CLI's shard: the tasks k with k mod 3 = 1.
    assert drop(plain(scalcal.sweep(**kw, shard="1/3"))) == [drop(one)[k] for k in (1, 4, 7)]
    assert drop(one) == drop(cli_json("sweep", "--positions", "9..12", "--criteria", "D,A", "--starts", "3",
                                      "--seed", "4", "--threads", "1"))
    with pytest.raises(scalcal.UsageError, match="give no shard"):
        scalcal.sweep(**kw, shard="0/2", map=map)


def test_pose_stream_is_calibrate_in_chunks():
    # A log given to PoseStream in chunks is the CLI's `calibrate --chunk` of the same rows (issue 51):
    # the same calibration file, key for key; given as one last chunk it is the batch `calibrate`.
    log = os.path.join(DATA, "xsens_acc.txt")
    rows = np.loadtxt(log)
    created = ("created", "tool", "stream")  # the file's time stamp; the CLI's chunk size (the stream's vary)
    for chunk in (500, len(rows)):
        s = scalcal.PoseStream("xsens_acc.txt")
        for k in range(0, len(rows), chunk):
            s.add(rows[k:k + chunk, 0], rows[k:k + chunk, 1:4], last=k + chunk >= len(rows))
        c = s.calibrate(magnitude=9.81744)
        args = ["calibrate", "--measurements", log, "--magnitude", "9.81744", "--out", "-"]
        expected = json.loads(cli(*args, *(["--chunk", str(chunk)] if chunk < len(rows) else [])).stdout)
        for key in expected:
            if key not in created and key != "data":
                assert plain(c[key]) == plain(expected[key]), (chunk, key)
        # Each pose's mean is the mean of its rows (numpy's, over the rows the pose spans with no break).
        poses = s.poses()
        assert len(poses) == 38
        whole = [p for p in poses if p["samples"] == p["end"] - p["begin"] + 1]
        assert len(whole) >= 30
        for p in whole:
            mean = rows[p["begin"]:p["end"] + 1, 1:4].mean(axis=0)
            assert np.allclose(p["mean"], mean, rtol=0, atol=1e-9 * 4e4)


def test_pose_stream_refuses_what_is_not_its_own():
    s = scalcal.PoseStream("s")
    with pytest.raises(scalcal.UsageError, match="samples an \\(n, 3\\) array"):
        s.add([0.0, 0.01], [[1.0, 2.0], [3.0, 4.0]])
    s.add([0.0, 0.01], [[1.0, 2.0, 3.0], [1.0, 2.0, 3.5]])
    with pytest.raises(scalcal.InputError, match="time does not increase"):
        s.add([0.005], [[1.0, 2.0, 3.0]])
    with pytest.raises(scalcal.UsageError, match="window belongs to the stream"):
        s.calibrate(magnitude=1.0, window=0.5)
    with pytest.raises(scalcal.UsageError, match="threshold_factor must be a positive number"):
        scalcal.PoseStream("t", threshold_factor=-1.0)


def test_build_info_says_what_the_build_holds():
    # A normal build has GiNaC and lacks nothing; a build without it (scripts/without_ginac.sh checks that one)
    # names `family` and `jig` as lacking.
    info = scalcal.build_info()
    assert info == {"version": scalcal.__version__, "ginac": True, "lacking": {}}
    assert "def build_info() -> dict[str, Any]: ..." in open(
        os.path.join(os.path.dirname(scalcal.__file__), "__init__.pyi")).read()


def test_an_empty_kernel_choice_is_none():
    # OPENBLAS_CORETYPE set but empty is no choice (OpenBLAS then picks the CPU's kernel): the module pins
    # Prescott as when it is unset, and as the CLI does (numeric/io/blas_kernel.hpp).
    env = dict(os.environ, OPENBLAS_CORETYPE="")
    r = subprocess.run([sys.executable, "-W", "error", "-c",
                        "import scalcal, os; print(scalcal._scalcal.blas_kernel(), os.environ['OPENBLAS_CORETYPE'])"],
                       capture_output=True, text=True, env=env)
    assert r.returncode == 0, r.stderr
    kernel, variable = r.stdout.split()
    assert variable == "Prescott"
    assert kernel == "Prescott", kernel
