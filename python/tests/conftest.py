# Shared fixtures for the Python tests: where the sources, the shared models
# and the command-line program are (CTest sets them; see python/CMakeLists.txt),
# and a reader for PFM files, to compare with what the program writes.
import os
import pathlib

import numpy as np
import pytest

SOURCE_DIR = pathlib.Path(os.environ.get("ZEROSET_SOURCE_DIR", pathlib.Path(__file__).parents[2]))
MODELS_DIR = pathlib.Path(os.environ.get("ZEROSET_MODELS_DIR", SOURCE_DIR.parent / "shared" / "models"))


@pytest.fixture
def binary():
    path = os.environ.get("ZEROSET_BINARY")
    if not path or not os.path.exists(path):
        pytest.skip("ZEROSET_BINARY does not name the zeroset program (run the tests through CTest)")
    return path


def read_pfm(path):
    """A colour PFM as float32 (height, width, 3), row 0 at the top."""
    with open(path, "rb") as f:
        assert f.readline().strip() == b"PF"
        width, height = map(int, f.readline().split())
        scale = float(f.readline())
        data = np.frombuffer(f.read(), dtype="<f4" if scale < 0 else ">f4")
    return data.reshape(height, width, 3)[::-1]
