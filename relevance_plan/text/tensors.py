"""Reading a safetensors file with numpy alone.

The format: 8 bytes, the little-endian length of a JSON header; the header,
an object mapping each tensor's name to its ``dtype``, ``shape`` and
``data_offsets`` (begin and end, in bytes, from the end of the header), with an
optional ``__metadata__`` entry; then the raw little-endian data.

The file is memory-mapped: arrays are read-only views of it, so only the
parts the encoder touches take memory (for the text model, the rows of the
words it meets, not its whole 47 MB word table).
"""

from __future__ import annotations

import json
import math
import mmap
import os
from typing import Any

import numpy as np
import numpy.typing as npt

from relevance_plan.errors import InputFileError

# Element types this reader knows, by the format's names.
DTYPES: dict[str, str] = {
    "F64": "<f8", "F32": "<f4", "F16": "<f2", "I64": "<i8", "I32": "<i4", "I16": "<i2", "I8": "i1"
}  # fmt: skip
# A header far larger than this is not a weight file's (the text model's is 11 KB).
MAX_HEADER_BYTES = 16 * 1024 * 1024
SIZE_BYTES = 8


def read_tensors(path: str | os.PathLike[str]) -> dict[str, npt.NDArray[Any]]:
    """Name -> read-only array for every tensor in the safetensors file at ``path``."""
    where = str(path)
    try:
        with open(path, "rb") as file:
            size = os.fstat(file.fileno()).st_size
            if size < SIZE_BYTES:
                raise InputFileError("not a safetensors file: shorter than its 8-byte header length", path=where)
            # An empty file cannot be mapped; one of 8 bytes or more can.
            mapped = mmap.mmap(file.fileno(), 0, access=mmap.ACCESS_READ)
    except FileNotFoundError:
        raise InputFileError("weight file not found", path=where) from None
    except IsADirectoryError:
        raise InputFileError("expected a weight file, found a directory", path=where) from None
    except OSError as error:
        raise InputFileError(f"cannot read the weight file: {error.strerror}", path=where) from None
    header_size = int.from_bytes(mapped[:SIZE_BYTES], "little")
    if header_size > min(MAX_HEADER_BYTES, size - SIZE_BYTES):
        raise InputFileError(f"not a safetensors file: header length {header_size} does not fit", path=where)
    try:
        header = json.loads(mapped[SIZE_BYTES : SIZE_BYTES + header_size].decode("utf-8"))
    except (UnicodeDecodeError, ValueError):
        raise InputFileError("not a safetensors file: its header is not JSON", path=where) from None
    if not isinstance(header, dict):
        raise InputFileError("not a safetensors file: its header is not a JSON object", path=where)
    data_start = SIZE_BYTES + header_size
    data_size = size - data_start
    tensors = {}
    for name, entry in header.items():
        if name == "__metadata__":
            continue
        dtype, shape, begin, end = _entry(name, entry, data_size, where)
        count = math.prod(shape)
        array = np.frombuffer(mapped, dtype=dtype, count=count, offset=data_start + begin)
        tensors[name] = array.reshape(shape)
    return tensors


def _entry(name: str, entry: Any, data_size: int, where: str) -> tuple[np.dtype[Any], tuple[int, ...], int, int]:
    def fail(why: str) -> InputFileError:
        return InputFileError(f"tensor {name!r}: {why}", path=where)

    if not isinstance(entry, dict):
        raise fail("its header entry is not an object")
    kind = entry.get("dtype")
    if kind not in DTYPES:
        raise fail(f"unknown dtype {kind!r}")
    shape = entry.get("shape")
    if not isinstance(shape, list) or not all(type(n) is int and n >= 0 for n in shape):
        raise fail("its shape is not a list of sizes")
    offsets = entry.get("data_offsets")
    if (
        not isinstance(offsets, list)
        or len(offsets) != 2
        or not all(type(n) is int for n in offsets)
        or not 0 <= offsets[0] <= offsets[1] <= data_size
    ):
        raise fail("its data offsets are not within the file")
    dtype = np.dtype(DTYPES[kind])
    if offsets[1] - offsets[0] != math.prod(shape) * dtype.itemsize:
        raise fail(f"{offsets[1] - offsets[0]} bytes for shape {shape} of {kind}")
    return dtype, tuple(shape), offsets[0], offsets[1]
