"""PDDL names for graph nodes: valid, and the same for a node whenever it is imported.

A node's name is its class (or ``place``), then its NodeSymbol: the symbol's
letter (an upper-case letter as its lower case, a lower-case one followed by
``_``, any other character as ``c<code>_``) and its index.  ``O(12)`` of class
cup is ``cup_o12``, ``p(657)`` is ``place_p_657``, ``R(3)`` of class kitchen
is ``kitchen_r3``.  Two nodes never share a name: the symbol part alone
differs for different ids, whatever their classes.
"""

from __future__ import annotations

import re

SYMBOL_BITS = 56  # a NodeSymbol's value: its character in the top byte, its index below
_INDEX_MASK = (1 << SYMBOL_BITS) - 1
_WORD = re.compile(r"[^a-z0-9_]+")
AGENT = "robot"


def symbol_parts(node_id: int) -> tuple[str, int]:
    """(the NodeSymbol's character, its index)."""
    return chr((node_id >> SYMBOL_BITS) & 0xFF), node_id & _INDEX_MASK


def symbol_tag(character: str) -> str:
    if "A" <= character <= "Z":
        return character.lower()
    if "a" <= character <= "z":
        return character + "_"
    return f"c{ord(character)}_"


def pddl_word(text: str) -> str:
    """A class name as a PDDL name: lower case, letters, digits and ``_``, starting with a letter."""
    word = _WORD.sub("_", text.lower()).strip("_") or "thing"
    return word if word[0].isalpha() else "k_" + word


def node_name(node_id: int, word: str) -> str:
    character, index = symbol_parts(node_id)
    return f"{pddl_word(word)}_{symbol_tag(character)}{index}"
