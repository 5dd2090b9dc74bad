"""Paths for the Python module's tests: ctest sets them (tests/CMakeLists.txt);
run by hand from the checkout, they default to build/."""
import os
import pathlib
import sys

SOURCE = pathlib.Path(os.environ.get("SANDSTORM_SOURCE_DIR", pathlib.Path(__file__).parents[2]))
BUILD = pathlib.Path(os.environ.get("SANDSTORM_BUILD_DIR", SOURCE / "build"))
sys.path.insert(0, str(BUILD / "python"))
