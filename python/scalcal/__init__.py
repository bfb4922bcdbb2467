"""scalcal: the scalar calibration of vector meters, from Python.

Every subcommand of the ``scalcal`` CLI is a function here with the same options: ``scalcal
optimize --positions 18 --criterion A --seed 3`` is ``scalcal.optimize(positions=18, criterion="A",
seed=3)``. The functions are made from the same option tables as the CLI's parser and --help, run the
same C++ and return the CLI's ``--json`` object as a dict (arrays of numbers as NumPy arrays). A
program may also be given as an (N, 3) array of directions. Warnings go to ``warnings.warn``; bad
input raises ``InputError``, bad options ``UsageError``, a result that did not converge
``ConvergenceError`` (its ``result`` attribute holds the result). Calls from several threads take
turns; Ctrl-C stops a long run within a second.
"""
import inspect
import json as _json
import os as _os
import warnings as _warnings

# The same numbers as the CLI on every CPU: OpenBLAS's generic kernel, which it reads when it loads
# (numeric/io/blas_kernel.hpp); checked below, since numpy imported first has loaded it already.
# An empty value counts as unset, as the CLI takes it (OpenBLAS would pick the CPU's kernel).
_KERNEL_CHOSEN = bool(_os.environ.get("OPENBLAS_CORETYPE"))
if not _KERNEL_CHOSEN:
    _os.environ["OPENBLAS_CORETYPE"] = "Prescott"

from . import _scalcal

# A package installed by pip carries the paper's tables beside it (setup.py); the C++ reads SCALCAL_DATA.
_DATA = _os.path.join(_os.path.dirname(__file__), "data")
if _os.path.isfile(_os.path.join(_DATA, "table1_A.csv")):
    _os.environ.setdefault("SCALCAL_DATA", _DATA)

__version__ = _scalcal.__version__
if not _KERNEL_CHOSEN and _scalcal.blas_kernel() not in ("", "Prescott"):
    _warnings.warn("OpenBLAS was loaded before scalcal (numpy imported first?) with its " + _scalcal.blas_kernel() +
                   " kernel: the last digits may differ from the CLI's; import scalcal first or set "
                   "OPENBLAS_CORETYPE=Prescott")
__all__ = ["Error", "InputError", "UsageError", "ConvergenceError", "ScalcalWarning", "Calibration", "program",
           "build_info"]


class Error(Exception):
    """Every error scalcal raises on purpose."""


class InputError(Error, ValueError):
    """Bad input data: a file, a program or an array (the CLI's exit status 2)."""


class UsageError(Error, ValueError):
    """Bad or contradicting arguments (the CLI's exit status 2)."""


class ConvergenceError(Error, RuntimeError):
    """A computation that did not converge; ``result`` holds what it reached (the CLI's exit status 1)."""

    def __init__(self, message, result):
        super().__init__(message)
        self.result = result


class ScalcalWarning(UserWarning):
    """What the CLI prints as ``scalcal COMMAND: warning: ...``."""


def _call(name, args, kwargs):
    try:
        result, warned, status = _scalcal.run(name, args, kwargs)
    except _scalcal.InputError as e:
        raise InputError(str(e)) from None
    except _scalcal.UsageError as e:
        raise UsageError(str(e)) from None
    for subject, message in warned:
        _warnings.warn(f"{subject}: {message}" if subject else message, ScalcalWarning, stacklevel=3)
    if status == 1:
        raise ConvergenceError(f"{name}: the result did not converge", result)
    return result


_KIND_TYPES = {"integer": int, "number": float, "flag": bool, "text": str, "choice": str,
               "positional": str, "repeated": list}


def _default(o):
    """The option's default as a Python value; None where the table states it in words."""
    d = o["default"]
    if not d or o["default_text"]:
        return False if o["kind"] == "flag" else None
    try:
        return {"integer": int, "number": float, "flag": lambda t: t == "1"}.get(o["kind"], str)(d)
    except ValueError:
        return None


def _make(table):
    name = table["name"]
    params, lines = [], []
    for o in table["options"]:
        kind = (inspect.Parameter.POSITIONAL_OR_KEYWORD if o["kind"] == "positional"
                else inspect.Parameter.KEYWORD_ONLY)
        default = inspect.Parameter.empty if o["required"] else _default(o)
        params.append(inspect.Parameter(o["name"], kind, default=default,
                                        annotation=_KIND_TYPES.get(o["kind"], str)))
        extra = (" Also an (N, 3) array of directions." if o["positions"] else
                 " Also a mapping column name -> 1-D array (the file's columns)." if o["columns"] else
                 " Also the object itself (a dict)." if o["document"] else "")
        choices = f" One of {', '.join(o['choices'])}." if o["choices"] else ""
        lines.append(f"    {o['name']} ({o['option']}): {o['help']}{choices}{extra}")
    # Required keyword-only parameters may follow optional ones; positional ones come first.
    params.sort(key=lambda p: p.kind != inspect.Parameter.POSITIONAL_OR_KEYWORD)

    def command(*args, **kwargs):
        return _call(name, args, kwargs)

    command.__name__ = command.__qualname__ = name
    command.__signature__ = inspect.Signature(params)
    command.__doc__ = (f"{table['summary']}.\n\nThe CLI's `{table['usage']}`; returns its --json object.\n\n"
                       "Arguments:\n" + "\n".join(lines))
    return command


def _plain(value):
    """A result as JSON's own types (lists for NumPy arrays), so that it json.dumps as it is."""
    if hasattr(value, "tolist"):
        return value.tolist()
    if isinstance(value, dict):
        return {k: _plain(v) for k, v in value.items()}
    if isinstance(value, list):
        return [_plain(v) for v in value]
    return value


class Calibration(dict):
    """A calibration: the object ``scalcal calibrate --out CAL.json`` writes, as a dict of JSON's own
    types (``json.dump(calibration, f)`` writes a file the CLI reads). ``offset`` and ``matrix`` are
    also NumPy arrays (physical = matrix (raw - offset)); ``save``/``load`` write and read cal.json;
    ``correct`` and ``export`` are ``scalcal.correct(calibration=self, ...)`` and
    ``scalcal.export(self, ...)``."""

    @property
    def offset(self):
        import numpy
        return numpy.asarray(self["offset"], dtype=float)

    @property
    def matrix(self):
        import numpy
        return None if self.get("matrix") is None else numpy.asarray(self["matrix"], dtype=float)

    def save(self, path):
        """Write the calibration as cal.json (what ``scalcal correct`` and ``export`` read)."""
        with open(path, "w", encoding="utf-8") as f:
            _json.dump(self, f, indent=2, allow_nan=False)
            f.write("\n")

    @classmethod
    def load(cls, path):
        """Read a calibration file (as ``scalcal correct`` would: checked when it is used)."""
        with open(path, encoding="utf-8") as f:
            return cls(_json.load(f))

    def correct(self, measurements, **kwargs):
        """The corrected measurements (``scalcal.correct(calibration=self, measurements=...)``)."""
        return globals()["correct"](calibration=dict(self), measurements=measurements, **kwargs)

    def export(self, format, **kwargs):
        """The calibration in another tool's form (``scalcal.export(self, format=...)``)."""
        return globals()["export"](dict(self), format=format, **kwargs)


for _table in _scalcal.tables():
    globals()[_table["name"]] = _make(_table)
    __all__.append(_table["name"])


def build_info():
    """What this build holds: ``{"version", "ginac", "lacking"}``. A build made with -DSCALCAL_WITH_GINAC=OFF
    (docs/install.md) has ``ginac`` False and lacks ``family`` and ``jig``: ``lacking`` maps each to the line
    the CLI gives for it, and calling it raises UsageError with that line."""
    return _scalcal.build_info()


def _lacking(name, message):
    def command(*args, **kwargs):
        raise UsageError(message)

    command.__name__ = command.__qualname__ = name
    command.__doc__ = f"Not in this build: {message}."
    return command


for _name, _message in _scalcal.build_info()["lacking"].items():
    globals()[_name] = _lacking(_name, _message)
    __all__.append(_name)

_calibrate_command = calibrate  # noqa: F821 (made from its table above)


def calibrate(*args, **kwargs):
    result = _calibrate_command(*args, **kwargs)
    return Calibration(_plain(result))


calibrate.__signature__ = _calibrate_command.__signature__
calibrate.__doc__ = (_calibrate_command.__doc__.replace("returns its --json object",
                                                        "returns the calibration file's object, a Calibration")
                     if _calibrate_command.__doc__ else None)


class PoseStream:
    """Still poses found as a log arrives, and the calibration of those settled so far: the CLI's
    ``calibrate --chunk`` one chunk at a time, for a bench script that reads a serial port.

    ``PoseStream(name="stream", still=None, window=None, threshold_factor=None, min_interval=None)``
    takes the detection's options as ``calibrate`` does (none given: every candidate of its adaptive
    choice is kept). ``add(t, samples, last=False)`` appends rows (t in seconds, samples an (n, 3)
    array of raw outputs); each sample is judged still or moving once, when half a window of rows after
    it has arrived, from the rows up to there (docs/calibrate.md). ``poses()`` lists the poses settled
    so far (rows from 0, seconds, samples, mean and per-output variance), ``state()`` the rows, chunks,
    window, noise floor and threshold, and ``calibrate(magnitude=..., **options)`` fits them with
    ``scalcal.calibrate``'s options and returns a Calibration; after ``last=True`` it is exactly
    ``scalcal.calibrate`` of the whole log."""

    def __init__(self, name="stream", *, still=None, window=None, threshold_factor=None, min_interval=None):
        self._stream = self._checked(_scalcal.PoseStream, name, still, window, threshold_factor, min_interval)

    @staticmethod
    def _checked(call, *args):
        try:
            return call(*args)
        except _scalcal.InputError as e:
            raise InputError(str(e)) from None
        except _scalcal.UsageError as e:
            raise UsageError(str(e)) from None

    def add(self, t, samples, last=False):
        import numpy
        self._checked(self._stream.add, numpy.asarray(t, dtype=float), numpy.asarray(samples, dtype=float),
                      bool(last))

    def poses(self):
        return self._checked(self._stream.poses)

    def state(self):
        return self._checked(self._stream.state)

    def calibrate(self, **kwargs):
        result, warned, status = self._checked(self._stream.calibrate, kwargs)
        for subject, message in warned:
            _warnings.warn(f"{subject}: {message}" if subject else message, ScalcalWarning, stacklevel=2)
        if status == 1:
            raise ConvergenceError("calibrate: the result did not converge", Calibration(_plain(result)))
        return Calibration(_plain(result))


__all__.append("PoseStream")

_sweep_command = sweep  # noqa: F821 (made from its table above)


def _sweep_shard(job):
    """One task of sweep(map=...): shard k of n, n the number of tasks (module level: a process pool pickles it)."""
    k, n, args, kwargs = job
    return _sweep_command(*args, shard=f"{k}/{n}", **kwargs)


def sweep(*args, map=None, **kwargs):
    if map is None:
        return _sweep_command(*args, **kwargs)
    if kwargs.get("shard") is not None:
        raise UsageError("sweep: map= runs every task as its own shard; give no shard with it")
    try:
        n = len(_scalcal.sweep_tasks(args, kwargs))
    except _scalcal.InputError as e:
        raise InputError(str(e)) from None
    except _scalcal.UsageError as e:
        raise UsageError(str(e)) from None
    rows = []
    for part in map(_sweep_shard, [(k, n, args, kwargs) for k in range(n)]):
        rows.extend(part)
    return rows


sweep.__signature__ = _sweep_command.__signature__.replace(
    parameters=list(_sweep_command.__signature__.parameters.values()) +
    [inspect.Parameter("map", inspect.Parameter.KEYWORD_ONLY, default=None)])
sweep.__doc__ = (_sweep_command.__doc__ or "") + (
    "\n    map: a map function (builtins.map, a process pool's or mpi4py's executor's map): each (criterion, N)"
    "\n        task runs as its own call through it, and the rows come back in task order, the same as one call's"
    "\n        (seconds aside). A thread pool gains nothing: calls into scalcal take turns.")


def program(name):
    """The (N, 3) positions of a catalogue program (``scalcal catalogue``), a family member or a CSV file."""
    try:
        return _scalcal.program(name)
    except _scalcal.InputError as e:
        raise InputError(str(e)) from None
