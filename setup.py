"""The build behind pyproject.toml: the extension contactcert._core and the CLI `contactcert` (packaged as
contactcert/bin/contactcert, which `python -m contactcert` runs) are built by the project's CMake, then packaged
with python/contactcert.

CONTACTCERT_BUILD_DIR: an existing CMake build folder to build the two targets in (scripts/test passes its own,
so that nothing is compiled twice); otherwise a Release build in setuptools' temporary folder. CMAKE_ARGS: more
arguments for a new configuration (e.g. -DCMAKE_CXX_COMPILER_LAUNCHER=ccache). CONTACTCERT_JOBS: parallel jobs
(default: the processors)."""

import os
import pathlib
import re
import shlex
import shutil
import subprocess
import sys

from setuptools import Extension, setup
from setuptools.command.build_ext import build_ext

ROOT = pathlib.Path(__file__).resolve().parent
VERSION = re.search(r"project\(contactcert VERSION ([0-9.]+)", (ROOT / "CMakeLists.txt").read_text()).group(1)


class CMakeBuild(build_ext):
    """Builds the targets contactcert_python and contactcert with CMake and puts them where setuptools expects."""

    def build_extension(self, ext: Extension) -> None:
        build = pathlib.Path(os.environ.get("CONTACTCERT_BUILD_DIR") or pathlib.Path(self.build_temp) / "cmake")
        if not (build / "CMakeCache.txt").exists():
            subprocess.run(["cmake", "-S", str(ROOT), "-B", str(build), "-G", "Ninja", "-DCMAKE_BUILD_TYPE=Release",
                            "-DCONTACTCERT_TESTS=OFF", "-DCONTACTCERT_BENCH=OFF", "-DCONTACTCERT_PYTHON=ON",
                            f"-DPython3_EXECUTABLE={sys.executable}",
                            *shlex.split(os.environ.get("CMAKE_ARGS", ""))], check=True)
        jobs = os.environ.get("CONTACTCERT_JOBS", str(os.cpu_count() or 1))
        subprocess.run(["cmake", "--build", str(build), "-j", jobs, "--target", "contactcert_python", "contactcert"],
                       check=True)
        core = next((build / "python" / "contactcert").glob("_core*.so"))
        target = pathlib.Path(self.get_ext_fullpath(ext.name))
        target.parent.mkdir(parents=True, exist_ok=True)
        shutil.copyfile(core, target)
        # The CLI inside the package (contactcert/bin), where `python -m contactcert` looks first.
        (target.parent / "bin").mkdir(exist_ok=True)
        shutil.copy2(build / "cli" / "contactcert", target.parent / "bin" / "contactcert")


setup(
    version=VERSION,
    packages=["contactcert"],
    package_dir={"contactcert": "python/contactcert"},
    package_data={"contactcert": ["py.typed", "_core.pyi"]},
    ext_modules=[Extension("contactcert._core", sources=[])],
    cmdclass={"build_ext": CMakeBuild},
    zip_safe=False,
    # setuptools' own folders beside the CMake build folders (build/ is CMake's), its metadata under them too.
    options={"build": {"build_base": "build-setuptools"}, "egg_info": {"egg_base": "build-setuptools"}},
)
