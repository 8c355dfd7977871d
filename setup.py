"""pip install . builds the Python module cgal_policies (docs/python.md) with CMake, for the Python
that runs pip, and installs it with its type hints. It needs the packages of run.sh's lists and
no network: pip finds setuptools and numpy among the system's packages (in a virtual environment
made with --system-site-packages)."""
import os
import pathlib
import shutil
import subprocess
import sys

from setuptools import Extension, setup
from setuptools.command.build_ext import build_ext

ROOT = pathlib.Path(__file__).resolve().parent
(ROOT / "build-pip").mkdir(exist_ok=True)  # egg_info's folder must exist


class CMakeBuild(build_ext):
    """Builds the one CMake target of the module and puts it where setuptools installs from."""

    def build_extension(self, ext):
        build = pathlib.Path(self.build_temp).resolve() / "cmake"
        subprocess.run(["cmake", "-S", str(ROOT), "-B", str(build), "-DCMAKE_BUILD_TYPE=Release",
                        "-DCGAL_POLICIES_BUILD_TESTS=OFF", "-DCGAL_POLICIES_BUILD_VIEWER=OFF",
                        "-DCGAL_POLICIES_BUILD_PYTHON=ON", f"-DPython_EXECUTABLE={sys.executable}"],
                       check=True)
        subprocess.run(["cmake", "--build", str(build), "--target", "cgal_policies_python",
                        "-j", str(os.cpu_count() or 1)], check=True)
        built = next((build / "python" / "cgal_policies").glob("_cgal_policies*.so"))
        target = pathlib.Path(self.get_ext_fullpath(ext.name))
        target.parent.mkdir(parents=True, exist_ok=True)
        shutil.copyfile(built, target)


setup(
    name="cgal_policies",
    version="0.1.0",
    description="Mesh simplification: CGAL edge-collapse policies, the fitting pass, seams kept",
    python_requires=">=3.9",
    install_requires=["numpy"],
    packages=["cgal_policies"],
    package_dir={"": "python"},
    package_data={"cgal_policies": ["*.pyi", "py.typed"]},
    ext_modules=[Extension("cgal_policies._cgal_policies", sources=[])],
    cmdclass={"build_ext": CMakeBuild},
    # Not setuptools' default build/, which is the CMake build of run.sh.
    options={"build": {"build_base": "build-pip"}, "egg_info": {"egg_base": "build-pip"}},
)
