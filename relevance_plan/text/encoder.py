"""A BERT sentence encoder in numpy: ids in, one unit vector per text out.

The forward pass of a BERT encoder (the architecture of all-MiniLM-L6-v2):

- embeddings: the word's row + its position's row + the first segment's
  row, layer-normalised;
- each layer: multi-head self-attention (scaled dot products, padding masked
  out, softmax), projected and added back, layer-normalised; then a
  feed-forward block (widen, GELU, narrow), added back, layer-normalised;
- the sentence: the mean of its tokens' last states (padding excluded),
  scaled to length 1, so a dot product of two sentences is their cosine.

Weights are named as in BERT checkpoints (``encoder.layer.0.attention.self.query.weight``,
...), each linear map stored as (out, in).  Everything is float32.
"""

from __future__ import annotations

import contextlib
import math
from collections.abc import Mapping, Sequence
from dataclasses import dataclass
from typing import Any

import numpy as np
import numpy.typing as npt

from relevance_plan.errors import InputFileError

FloatArray = npt.NDArray[np.float32]
# Texts embedded together, padded to the longest of them: sorting by length keeps padding small.
BATCH_SIZE = 32
# A score far below any real one: masked positions get no attention at all after the softmax.
_MASKED = np.float32(-1e9)


@dataclass(frozen=True)
class Linear:
    """y = x W + b, with W stored (in, out) in memory of its own: a product with a memory-mapped,
    transposed matrix ran ten times slower."""

    weight: FloatArray  # (in, out)
    bias: FloatArray  # (out,)

    @classmethod
    def from_checkpoint(cls, weight: FloatArray, bias: FloatArray) -> Linear:
        """From a checkpoint's (out, in) matrix."""
        return cls(np.ascontiguousarray(weight.T, dtype=np.float32), np.array(bias, dtype=np.float32))

    def __call__(self, x: FloatArray) -> FloatArray:
        # One 2-D product for the whole batch: numpy's stacked 3-D product is several times slower.
        flat = x.reshape(-1, x.shape[-1]) @ self.weight + self.bias
        return np.asarray(flat.reshape(*x.shape[:-1], self.weight.shape[1]), dtype=np.float32)


@dataclass(frozen=True)
class LayerNorm:
    scale: FloatArray
    shift: FloatArray
    epsilon: float

    def __call__(self, x: FloatArray) -> FloatArray:
        mean = x.mean(axis=-1, keepdims=True)
        centred = x - mean
        variance = (centred * centred).mean(axis=-1, keepdims=True)
        return np.asarray(centred / np.sqrt(variance + self.epsilon) * self.scale + self.shift, dtype=np.float32)


@dataclass(frozen=True)
class EncoderLayer:
    query: Linear
    key: Linear
    value: Linear
    attention_output: Linear
    attention_norm: LayerNorm
    widen: Linear
    narrow: Linear
    output_norm: LayerNorm


def one_blas_thread() -> contextlib.AbstractContextManager[object]:
    """Matrix products on one thread while embedding.

    These products are small: a second BLAS thread gains little on an idle
    machine, and on a busy one (a planner running beside) its threads wait on
    each other and one embedding took five times longer.  Without
    threadpoolctl (part of the ``text`` extra), BLAS keeps its own setting.
    """
    try:
        from threadpoolctl import threadpool_limits
    except ImportError:
        return contextlib.nullcontext()
    return threadpool_limits(1, user_api="blas")  # type: ignore[no-any-return]


def gelu(x: FloatArray) -> FloatArray:
    """x · Φ(x), with Φ from erf (not the tanh approximation), as BERT was trained."""
    return np.asarray(0.5 * x * (1.0 + erf(x / np.float32(math.sqrt(2.0)))), dtype=np.float32)


def erf(x: FloatArray) -> FloatArray:
    """The error function to within 1.5e-7 (Abramowitz and Stegun, 7.1.26): numpy has none."""
    sign = np.sign(x)
    a = np.abs(x)
    t = 1.0 / (1.0 + 0.3275911 * a)
    polynomial = t * (0.254829592 + t * (-0.284496736 + t * (1.421413741 + t * (-1.453152027 + t * 1.061405429))))
    return np.asarray(sign * (1.0 - polynomial * np.exp(-a * a)), dtype=np.float32)


class SentenceEncoder:
    """BERT weights, ready to embed batches of token ids (see :meth:`embed_ids`)."""

    def __init__(
        self,
        tensors: Mapping[str, npt.NDArray[Any]],
        heads: int,
        epsilon: float = 1e-12,
        padding_id: int = 0,
        source: str = "<weights>",
    ):
        self.source = source
        get = _TensorGetter(tensors, source)
        self.words = get("embeddings.word_embeddings.weight", 2)
        width = self.words.shape[1]
        if heads < 1 or width % heads:
            raise InputFileError(f"a width of {width} does not split into {heads} attention heads", path=source)
        self.heads = heads
        self.width = width
        self.positions = get("embeddings.position_embeddings.weight", 2, columns=width)
        self.segment = get("embeddings.token_type_embeddings.weight", 2, columns=width)[0]
        self.embedding_norm = get.norm("embeddings.LayerNorm", width, epsilon)
        self.padding_id = padding_id
        layers: list[EncoderLayer] = []
        while f"encoder.layer.{len(layers)}.attention.self.query.weight" in tensors:
            layers.append(get.layer(f"encoder.layer.{len(layers)}", width, epsilon))
        if not layers:
            raise InputFileError("no encoder layers (encoder.layer.0...) in the weights", path=source)
        self.layers = tuple(layers)

    @property
    def max_ids(self) -> int:
        return int(self.positions.shape[0])

    def embed_ids(self, sequences: Sequence[Sequence[int]]) -> FloatArray:
        """One unit vector per id sequence, in the order given: (len(sequences), width)."""
        result = np.zeros((len(sequences), self.width), dtype=np.float32)
        order = sorted(range(len(sequences)), key=lambda i: len(sequences[i]))
        with one_blas_thread():
            for start in range(0, len(order), BATCH_SIZE):
                chosen = order[start : start + BATCH_SIZE]
                result[chosen] = self._embed_batch([sequences[i] for i in chosen])
        return result

    def _embed_batch(self, sequences: Sequence[Sequence[int]]) -> FloatArray:
        length = max(len(ids) for ids in sequences)
        if length > self.max_ids:
            raise InputFileError(
                f"a text of {length} ids is longer than the model reads ({self.max_ids})", path=self.source
            )
        ids = np.full((len(sequences), length), self.padding_id, dtype=np.int64)
        mask = np.zeros((len(sequences), length), dtype=bool)
        for row, sequence in enumerate(sequences):
            ids[row, : len(sequence)] = sequence
            mask[row, : len(sequence)] = True
        if (ids >= self.words.shape[0]).any() or (ids < 0).any():
            raise InputFileError("a token id outside the model's vocabulary", path=self.source)
        states = self.hidden_states(ids, mask)
        weights = mask[:, :, None].astype(np.float32)
        pooled = (states * weights).sum(axis=1) / np.maximum(weights.sum(axis=1), 1e-9)
        norms = np.linalg.norm(pooled, axis=1, keepdims=True)
        return np.asarray(pooled / np.maximum(norms, 1e-12), dtype=np.float32)

    def hidden_states(self, ids: npt.NDArray[np.int64], mask: npt.NDArray[np.bool_]) -> FloatArray:
        """The last layer's states, (batch, length, width), for right-padded ``ids``."""
        batch, length = ids.shape
        x = self.embedding_norm(self.words[ids] + self.positions[:length] + self.segment)
        # Padding is never attended to: a large negative score before the softmax.
        blocked = np.where(mask, np.float32(0.0), _MASKED)[:, None, None, :]
        for layer in self.layers:
            x = self._layer(layer, x, blocked)
        return x

    def _layer(self, layer: EncoderLayer, x: FloatArray, blocked: FloatArray) -> FloatArray:
        batch, length, width = x.shape
        size = width // self.heads

        def split(y: FloatArray) -> FloatArray:  # (batch, length, width) -> (batch, heads, length, size)
            heads: FloatArray = y.reshape(batch, length, self.heads, size).transpose(0, 2, 1, 3)
            return heads

        query, key, value = split(layer.query(x)), split(layer.key(x)), split(layer.value(x))
        scores = query @ key.transpose(0, 1, 3, 2) / np.float32(math.sqrt(size)) + blocked
        scores -= scores.max(axis=-1, keepdims=True)
        attention = np.exp(scores)
        attention /= attention.sum(axis=-1, keepdims=True)
        context = (attention @ value).transpose(0, 2, 1, 3).reshape(batch, length, width)
        x = layer.attention_norm(x + layer.attention_output(context))
        return layer.output_norm(np.asarray(x + layer.narrow(gelu(layer.widen(x))), dtype=np.float32))


class _TensorGetter:
    """Named tensors, each checked for its shape and taken as float32."""

    def __init__(self, tensors: Mapping[str, npt.NDArray[Any]], source: str):
        self.tensors = tensors
        self.source = source

    def __call__(self, name: str, dimensions: int, rows: int | None = None, columns: int | None = None) -> FloatArray:
        array = self.tensors.get(name)
        if array is None:
            raise InputFileError(f"the weights lack {name}", path=self.source)
        expected = (rows, columns) if dimensions == 2 else (rows,)
        if array.ndim != dimensions or any(
            want is not None and have != want for have, want in zip(array.shape, expected)
        ):
            raise InputFileError(f"{name} has shape {tuple(array.shape)}, expected {expected}", path=self.source)
        return np.asarray(array, dtype=np.float32)

    def linear(self, name: str, inputs: int, outputs: int | None = None) -> Linear:
        weight = self(f"{name}.weight", 2, rows=outputs, columns=inputs)
        return Linear.from_checkpoint(weight, self(f"{name}.bias", 1, rows=weight.shape[0]))

    def norm(self, name: str, width: int, epsilon: float) -> LayerNorm:
        return LayerNorm(self(f"{name}.weight", 1, rows=width), self(f"{name}.bias", 1, rows=width), epsilon)

    def layer(self, name: str, width: int, epsilon: float) -> EncoderLayer:
        widen = self.linear(f"{name}.intermediate.dense", width)
        return EncoderLayer(
            query=self.linear(f"{name}.attention.self.query", width, width),
            key=self.linear(f"{name}.attention.self.key", width, width),
            value=self.linear(f"{name}.attention.self.value", width, width),
            attention_output=self.linear(f"{name}.attention.output.dense", width, width),
            attention_norm=self.norm(f"{name}.attention.output.LayerNorm", width, epsilon),
            widen=widen,
            narrow=self.linear(f"{name}.output.dense", widen.weight.shape[1], width),
            output_norm=self.norm(f"{name}.output.LayerNorm", width, epsilon),
        )
