"""The setuptools side of pyproject.toml: builds the extension poinsot._core with the project's own CMake.

The extension is the CMake target `poinsot_python` (python/CMakeLists.txt). This file configures the project
into build/wheel with only the library and that module (no command-line tool, tests, benchmarks or examples),
for the interpreter that runs the build (the venv's python3), builds that one target and hands the module
file to setuptools, which packs it with python/poinsot/*.py and the stubs *.pyi. Version and description
are read from the project() call of CMakeLists.txt, where C++, the tool and the Python module also get them.

Environment (all optional):
  POINSOT_CMAKE_BUILD_DIR      an existing build tree to use instead of build/wheel, e.g. build/release
                               (its Python must be the same interpreter: the module's suffix is checked);
  CMAKE_BUILD_PARALLEL_LEVEL   build jobs (CMake's own variable; default: the number of cores);
  CMAKE_CXX_COMPILER_LAUNCHER  e.g. ccache (CMake's own variable, read at the first configure).
"""
import os
import re
import shutil
import sys
import sysconfig
from pathlib import Path

from setuptools import Extension, setup
from setuptools.command.build_ext import build_ext

ROOT = Path(__file__).resolve().parent


def project_metadata():
    """(version, description) from `project(poinsot VERSION x.y.z DESCRIPTION "...")` of CMakeLists.txt."""
    text = (ROOT / "CMakeLists.txt").read_text(encoding="utf-8")
    m = re.search(r'project\(\s*poinsot\s+VERSION\s+([0-9]+\.[0-9]+\.[0-9]+)\s+DESCRIPTION\s+"([^"]*)"', text)
    if m is None:
        raise RuntimeError('CMakeLists.txt: expected project(poinsot VERSION x.y.z DESCRIPTION "...")')
    return m.group(1), m.group(2)


class CMakeBuild(build_ext):
    """build_ext that runs CMake instead of compiling sources itself."""

    def build_extension(self, ext):
        build_dir = Path(os.environ.get("POINSOT_CMAKE_BUILD_DIR") or ROOT / "build" / "wheel")
        if not build_dir.is_absolute():
            build_dir = ROOT / build_dir
        if not (build_dir / "CMakeCache.txt").exists():
            configure = [
                "cmake", "-S", str(ROOT), "-B", str(build_dir),
                "-DCMAKE_BUILD_TYPE=Release",
                f"-DPython_EXECUTABLE={sys.executable}",
                "-DPOINSOT_BUILD_PYTHON=ON",
                "-DPOINSOT_BUILD_CLI=OFF",
                "-DPOINSOT_BUILD_TESTS=OFF",
                "-DPOINSOT_BUILD_BENCHMARKS=OFF",
                "-DPOINSOT_BUILD_EXAMPLES=OFF",
            ]  # fmt: skip
            if shutil.which("ninja"):
                configure += ["-G", "Ninja"]
            self.spawn(configure)
        build = ["cmake", "--build", str(build_dir), "--target", "poinsot_python"]
        if "CMAKE_BUILD_PARALLEL_LEVEL" not in os.environ:
            build += ["--parallel", str(os.cpu_count() or 1)]
        self.spawn(build)

        suffix = sysconfig.get_config_var("EXT_SUFFIX")
        built = build_dir / "python" / "poinsot" / f"_core{suffix}"
        if not built.exists():
            found = sorted(p.name for p in (build_dir / "python" / "poinsot").glob("_core*"))
            raise RuntimeError(
                f"{built}: not found (found {found or 'nothing'}); the build tree {build_dir} was configured for "
                f"another Python than {sys.executable}"
            )
        target = Path(self.get_ext_fullpath(ext.name))
        target.parent.mkdir(parents=True, exist_ok=True)
        shutil.copyfile(built, target)


version, description = project_metadata()
setup(
    version=version,
    description=description,
    ext_modules=[Extension("poinsot._core", sources=[])],
    cmdclass={"build_ext": CMakeBuild},
)
