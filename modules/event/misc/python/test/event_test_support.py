"""Helpers of the Python tests (these and test/python's): where the real recordings and the command-line tools are."""
import os
import pathlib
import shutil

import pytest

REPO = pathlib.Path(__file__).resolve().parents[5]


def data_dir():
    """The real recordings beside the repository (../shared/data), or OPENCV_EVENT_DATA."""
    return pathlib.Path(os.environ.get("OPENCV_EVENT_DATA", REPO.parent / "shared" / "data"))


def require_recording(relative):
    """The path of a real recording, or a skip that says which one is missing."""
    path = data_dir() / relative
    if not path.exists():
        pytest.skip("%s not found (the real recordings are not part of the repository)" % path)
    return path


def require_tool(name):
    """A command-line tool of the standalone build: OPENCV_EVENT_TOOLS (a folder), else on PATH, else a skip."""
    folder = os.environ.get("OPENCV_EVENT_TOOLS")
    path = os.path.join(folder, name) if folder else shutil.which(name)
    if not path or not os.access(path, os.X_OK):
        pytest.skip("%s not found: set OPENCV_EVENT_TOOLS to the folder of the built samples" % name)
    return path
