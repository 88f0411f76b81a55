# The C extension only; the rest of the package is in pyproject.toml.
from setuptools import setup

setup(cffi_modules=["daran_build.py:ffibuilder"])
