"""pip install ./app/python: builds the native module with the repository's CMake (target
visemelab_python) for the interpreter running pip, and installs the package visemelab.

The build folder is build/pip in the repository (kept between installs: a reinstall only rebuilds
what changed); VISEMELAB_PIP_BUILD_DIR names another, VISEMELAB_CMAKE_ARGS adds CMake arguments.
The package reads the repository's assets (the bundled phoneme tables), so keep the checkout.
"""

import os
import pathlib
import re
import shlex
import shutil
import subprocess
import sys

from setuptools import Extension, setup
from setuptools.command.build_ext import build_ext

HERE = pathlib.Path(__file__).resolve().parent
ROOT = HERE.parent.parent


def project_version():
    text = (ROOT / "CMakeLists.txt").read_text()
    return re.search(r"project\(VisemeLab VERSION ([0-9.]+)", text).group(1)


class CMakeExtension(Extension):
    def __init__(self, name):
        super().__init__(name, sources=[])


class CMakeBuild(build_ext):
    def build_extension(self, ext):
        build_dir = pathlib.Path(os.environ.get("VISEMELAB_PIP_BUILD_DIR", ROOT / "build" / "pip"))
        configure = [
            "cmake", "-S", str(ROOT), "-B", str(build_dir), "-G", "Ninja",
            "-DCMAKE_BUILD_TYPE=Release",
            # The release preset's batching, so ccache shares objects with a build of the presets.
            "-DCMAKE_UNITY_BUILD=ON", "-DCMAKE_UNITY_BUILD_BATCH_SIZE=16",
            "-DVISEMELAB_BUILD_TESTS=OFF", "-DVISEMELAB_BUILD_EDITOR=OFF",
            "-DVISEMELAB_BUILD_BENCHMARKS=OFF", "-DVISEMELAB_BUILD_PYTHON=ON",
            f"-DVISEMELAB_PYTHON_EXECUTABLE={sys.executable}",
        ] + shlex.split(os.environ.get("VISEMELAB_CMAKE_ARGS", ""))
        subprocess.check_call(configure)
        jobs = str(os.cpu_count() or 1)
        subprocess.check_call(["cmake", "--build", str(build_dir), "--target", "visemelab_python", "-j", jobs])
        built = sorted((build_dir / "app" / "python" / "visemelab").glob("_core*.so"))
        if not built:
            raise RuntimeError(f"the build in {build_dir} made no visemelab/_core module")
        destination = pathlib.Path(self.get_ext_fullpath(ext.name))
        destination.parent.mkdir(parents=True, exist_ok=True)
        shutil.copyfile(built[0], destination)


setup(
    name="visemelab",
    version=project_version(),
    description="VisemeLab's core: optimal viseme reduction, avatar reduction, speech, batches",
    packages=["visemelab"],
    ext_modules=[CMakeExtension("visemelab._core")],
    cmdclass={"build_ext": CMakeBuild},
    python_requires=">=3.9",
    install_requires=["numpy"],
    extras_require={"dask": ["dask", "distributed"]},
    zip_safe=False,
)
