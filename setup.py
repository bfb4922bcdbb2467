# The build step of `pip install .` (pyproject.toml): configures the project's CMake build, builds only
# the extension target scalcal_python, and puts in the wheel the extension, the package python/scalcal
# with its generated stubs, and the paper's tables (data/, which scalcal/__init__.py points SCALCAL_DATA at).
# The CMake build goes to build-pip/ (kept: a second install rebuilds only what changed); SCALCAL_BUILD_DIR
# reuses a configured build folder instead (e.g. build); SCALCAL_CMAKE_ARGS adds configure options.
import glob
import os
import shlex
import shutil
import subprocess
import sys

from setuptools import Extension, setup
from setuptools.command.build_ext import build_ext

ROOT = os.path.dirname(os.path.abspath(__file__))


class CMakeBuild(build_ext):
    """Builds scalcal._scalcal with CMake instead of setuptools' compiler calls."""

    def build_extension(self, ext):
        given = os.environ.get("SCALCAL_BUILD_DIR")
        # build-pip beside build/: the same depth, so ccache (base_dir) serves objects build/ compiled.
        build = os.path.abspath(given or os.path.join(ROOT, "build-pip"))
        # A build folder of the user's keeps its configuration; setup.py's own is configured each time, as
        # the interpreter (a virtualenv's) may have changed since the last install.
        if not given or not os.path.exists(os.path.join(build, "CMakeCache.txt")):
            self.configure(build)
        jobs = os.environ.get("CMAKE_BUILD_PARALLEL_LEVEL") or str(os.cpu_count() or 1)
        subprocess.run(["cmake", "--build", build, "--target", "scalcal_python", "--parallel", jobs], check=True)
        built = glob.glob(os.path.join(build, "python", "scalcal", "_scalcal*.so"))
        if len(built) != 1:
            sys.exit(f"scalcal: expected one _scalcal*.so in {build}/python/scalcal, found {built}")
        target = self.get_ext_fullpath(ext.name)
        package = os.path.dirname(target)
        os.makedirs(package, exist_ok=True)
        shutil.copyfile(built[0], target)
        for stub in ("__init__.pyi", "py.typed"):  # written by the build (python/CMakeLists.txt)
            shutil.copyfile(os.path.join(build, "python", "scalcal", stub), os.path.join(package, stub))
        shutil.copytree(os.path.join(ROOT, "data"), os.path.join(package, "data"), dirs_exist_ok=True)

    def configure(self, build):
        # The module for this very interpreter; no tests, benchmarks or MPI: only what the module links.
        args = ["cmake", "-S", ROOT, "-B", build, "-DCMAKE_BUILD_TYPE=Release", f"-DPython_EXECUTABLE={sys.executable}",
                "-DSCALCAL_BUILD_TESTS=OFF", "-DSCALCAL_BENCH=OFF", "-DSCALCAL_MPI=OFF"]
        if shutil.which("ninja"):
            args.append("-GNinja")
        if not os.environ.get("CXX") and shutil.which("clang++"):  # the project's default: half g++'s time
            args.append("-DCMAKE_CXX_COMPILER=clang++")
        if shutil.which("ccache"):
            args.append("-DCMAKE_CXX_COMPILER_LAUNCHER=ccache")
        args += shlex.split(os.environ.get("SCALCAL_CMAKE_ARGS", ""))
        subprocess.run(args, check=True)


setup(
    packages=["scalcal"],
    package_dir={"scalcal": "python/scalcal"},
    ext_modules=[Extension("scalcal._scalcal", sources=[])],
    cmdclass={"build_ext": CMakeBuild},
    options={"build": {"build_base": os.path.join("build-pip", "setuptools")}},
    zip_safe=False,
)
