"""Builds the envdesign-client package: the client modules and the LCM message types, which
lcm-gen writes from lcmtypes/envdesign/*.lcm into the build (generated code is never
committed). The version is CMake's project(VERSION), the one version of envdesign.

$ENVDESIGN_LCMTYPES names the folder of the .lcm files when this folder is not in the
repository (default: ../../lcmtypes/envdesign)."""
import glob
import os
import pathlib
import re
import shutil
import subprocess

from setuptools import setup
from setuptools.command.build_py import build_py

HERE = pathlib.Path(__file__).resolve().parent
ROOT = HERE.parent.parent


def lcm_types_dir():
    folder = pathlib.Path(os.environ.get("ENVDESIGN_LCMTYPES", ROOT / "lcmtypes" / "envdesign"))
    if not list(folder.glob("*.lcm")):
        raise SystemExit(f"envdesign-client: no LCM types (*.lcm) in {folder}; "
                         "set ENVDESIGN_LCMTYPES to lcmtypes/envdesign of the repository")
    return folder


def version():
    cmake = (ROOT / "CMakeLists.txt").read_text()
    found = re.search(r"project\(envdesign VERSION ([0-9.]+)", cmake)
    if not found:
        raise SystemExit(f"envdesign-client: no project(envdesign VERSION ...) in {ROOT}/CMakeLists.txt")
    return found.group(1)


class BuildWithTypes(build_py):
    """build_py, then lcm-gen --python into the build: the `envdesign` package of types."""

    def run(self):
        super().run()
        lcm_gen = shutil.which("lcm-gen")
        if not lcm_gen:
            raise SystemExit("envdesign-client: lcm-gen not found (Debian: liblcm-bin)")
        types = sorted(glob.glob(str(lcm_types_dir() / "*.lcm")))
        subprocess.run([lcm_gen, "--python", "--ppath", self.build_lib] + types, check=True)


setup(version=version(), py_modules=["envdesign_client", "envdesign_auth", "envdesign_text"],
      cmdclass={"build_py": BuildWithTypes})
