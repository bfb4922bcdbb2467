# Issue 50 item 6: the Python module as safe as the CLI. Calls from several threads take turns (GiNaC,
# CLN, Ipopt and MUMPS are not thread-safe: two threads crashed the interpreter) and give what one
# thread gives; Ctrl-C stops a long call within a second; NumPy scalars are numbers; argument errors
# name the argument; a column given twice (IX and ix) is refused as the CSV reader refuses it.
import os
import signal
import threading
import time

import numpy as np
import pytest

import scalcal


def without_seconds(result):
    """The result as plain lists and dicts, the run time left out (it is the only key that varies)."""
    if isinstance(result, np.ndarray):
        return without_seconds(result.tolist())
    if isinstance(result, dict):
        return {k: without_seconds(v) for k, v in result.items() if k != "seconds"}
    if isinstance(result, list):
        return [without_seconds(v) for v in result]
    return result


def same(a, b):
    assert a == b


CALLS = [
    lambda: scalcal.catalogue(),
    lambda: scalcal.evaluate("jig:cuboctahedron@orientation=aa:1,2,3,40"),
    lambda: scalcal.family("octahedral", param=["axes=2", "edges=1"]),
    lambda: {"positions": scalcal.program("icosahedral-20")},
    lambda: scalcal.optimize(positions=10, criterion="E", starts=2, seed=1, threads=1),  # Ipopt and MUMPS
]


def test_threads_take_turns_and_agree():
    expected = [without_seconds(c()) for c in CALLS]
    errors, results = [], {}

    def worker(t):
        try:
            for k in range(3):
                i = (t + k) % len(CALLS)
                results[(t, k)] = (i, without_seconds(CALLS[i]()))
        except BaseException as e:  # noqa: BLE001 - reported below
            errors.append(e)

    threads = [threading.Thread(target=worker, args=(t,)) for t in range(4)]
    for t in threads:
        t.start()
    for t in threads:
        t.join()
    assert not errors, errors
    assert len(results) == 12
    for i, r in results.values():
        same(r, expected[i])


class Stopped(Exception):
    pass


def stops_within_a_second(call, after=0.5):
    """Sends SIGINT `after` seconds into `call` and returns how long the call took to stop."""
    def handler(signum, frame):
        raise Stopped()

    previous = signal.signal(signal.SIGINT, handler)
    sent = []
    timer = threading.Timer(after, lambda: (sent.append(time.monotonic()), os.kill(os.getpid(), signal.SIGINT)))
    try:
        timer.start()
        with pytest.raises(Stopped):
            call()
        stopped = time.monotonic()
    finally:
        timer.cancel()
        timer.join()
        signal.signal(signal.SIGINT, previous)
    assert sent, "the call ended before the signal"
    return stopped - sent[0]


LONG_CALLS = {
    "random": lambda: scalcal.random(positions=1000, count=10**8, threads=1),
    "polish": lambda: scalcal.polish("random-40", criterion="D", digits=60),
    "limits": lambda: scalcal.limits(region=["band:20:160:1,2,3", "cap:10"]),
    "optimize": lambda: scalcal.optimize(positions=300, criterion="D", starts=1000, threads=1),
    "sweep": lambda: scalcal.sweep(positions="40..90", criteria="D", starts=100, threads=1),
}


@pytest.mark.parametrize("name", sorted(LONG_CALLS))
def test_ctrl_c_stops_a_long_call_within_a_second(name):
    assert stops_within_a_second(LONG_CALLS[name]) < 1.0
    # The module is usable at once after (the stop request was cleared).
    assert scalcal.evaluate("classic18")["positions"] == 18


def test_numpy_scalars_are_numbers():
    plain = without_seconds(scalcal.random(positions=12, count=50, seed=3, threads=1))
    numpy = without_seconds(scalcal.random(positions=np.int64(12), count=np.int32(50), seed=np.uint16(3),
                                           threads=np.int8(1)))
    same(numpy, plain)
    noise = np.float32(1e-3)
    a = scalcal.simulate(program="classic18", trials=np.int64(3), noise=noise, seed=2)
    b = scalcal.simulate(program="classic18", trials=3, noise=float(noise), seed=2)
    assert a["noise"] == float(noise)
    same(without_seconds(a), without_seconds(b))


@pytest.mark.parametrize("value", [True, np.bool_(True), "12", 12.5])
def test_what_is_not_an_integer_is_refused_by_name(value):
    with pytest.raises(scalcal.UsageError, match="positions: must be an int"):
        scalcal.random(positions=value, count=5)


def test_argument_errors_name_the_argument():
    with pytest.raises(TypeError, match=r"catalogue\(\) takes 0 positional arguments but 1 was given"):
        scalcal.catalogue(1)
    with pytest.raises(TypeError, match=r"evaluate\(\) takes 1 positional argument but 2 were given"):
        scalcal.evaluate("classic18", "classic18")
    with pytest.raises(scalcal.UsageError, match="positions"):
        scalcal.random(positions=10**30, count=5)
    with pytest.raises(scalcal.UsageError, match="seed"):
        scalcal.random(positions=12, count=5, seed=2**64)
    with pytest.raises(scalcal.UsageError, match="noise"):
        scalcal.simulate(program="classic18", trials=2, noise=10**400)


def test_a_column_given_twice_is_refused():
    rng = np.random.default_rng(1)
    columns = {name: rng.normal(size=40) for name in ("IX", "ix", "iy", "iz")}
    with pytest.raises(scalcal.InputError, match="appears twice"):
        scalcal.calibrate(measurements=columns, magnitude=1)
