# Builds the spectralseg Python module for `pip install .` (pyproject.toml)
# with the project's CMake build: only the module's target, in Release, for
# the interpreter that runs pip.
#
# The build folder is build-pip/ in the checkout (kept, so that a second
# install recompiles nothing), or SPECTRALSEG_BUILD_DIR. When that folder
# already holds a configured build (CMakeCache.txt), it is not configured
# again: `SPECTRALSEG_BUILD_DIR=build pip install --no-build-isolation .`
# installs the module of an existing build, rebuilding it if its sources
# changed.
import os
import re
import shutil
import subprocess
import sys

from setuptools import Extension, setup
from setuptools.command.build_ext import build_ext

HERE = os.path.dirname(os.path.abspath(__file__))


def version():
    text = open(os.path.join(HERE, "include", "SpectralSeg", "version.h")).read()
    parts = [re.search(r"#define SPECTRALSEG_VERSION_%s (\d+)" % p, text).group(1) for p in ("MAJOR", "MINOR", "PATCH")]
    return ".".join(parts)


class CMakeExtension(Extension):
    def __init__(self, name):
        super().__init__(name, sources=[])


class CMakeBuild(build_ext):
    def build_extension(self, ext):
        if shutil.which("cmake") is None:
            raise RuntimeError("spectralseg: cmake is needed to build the module (Debian: bash scripts/setup.sh)")
        build = os.path.abspath(os.environ.get("SPECTRALSEG_BUILD_DIR", os.path.join(HERE, "build-pip")))
        if not os.path.exists(os.path.join(build, "CMakeCache.txt")):
            subprocess.check_call([
                "cmake", "-S", HERE, "-B", build,
                "-DCMAKE_BUILD_TYPE=Release",
                "-DPython3_EXECUTABLE=" + sys.executable,
                "-DSPECTRALSEG_BUILD_PYTHON=ON",
                "-DSPECTRALSEG_BUILD_TESTS=OFF", "-DSPECTRALSEG_BUILD_EXAMPLES=OFF",
                "-DSPECTRALSEG_BUILD_BENCHMARKS=OFF", "-DSPECTRALSEG_BUILD_TOOLS=OFF",
                "-DSPECTRALSEG_BUILD_DOCS=OFF",
            ])
        subprocess.check_call(["cmake", "--build", build, "--target", "spectralseg_python",
                               "--parallel", str(os.cpu_count() or 1)])
        built = [f for f in os.listdir(os.path.join(build, "python"))
                 if f.startswith("spectralseg") and f.endswith(".so")]
        if not built:
            raise RuntimeError("spectralseg: the build made no module in " + os.path.join(build, "python") +
                               " (is pybind11-dev installed? bash scripts/setup.sh)")
        target = self.get_ext_fullpath(ext.name)
        os.makedirs(os.path.dirname(target), exist_ok=True)
        shutil.copyfile(os.path.join(build, "python", built[0]), target)


setup(version=version(), packages=[], py_modules=[], ext_modules=[CMakeExtension("spectralseg")],
      cmdclass={"build_ext": CMakeBuild})
