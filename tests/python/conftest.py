"""Shared set-up of the Python tests: the module built in build/python (ctest sets PYTHONPATH;
run by hand: PYTHONPATH=build/python python3 -m pytest tests/python)."""
import os
import sys

_binary = os.environ.get("SYMREP_BINARY_DIR")
if _binary and os.path.join(_binary, "python") not in sys.path:
    sys.path.insert(0, os.path.join(_binary, "python"))

SOURCE_DIR = os.environ.get("SYMREP_SOURCE_DIR", os.path.abspath(os.path.join(os.path.dirname(__file__), "..", "..")))
