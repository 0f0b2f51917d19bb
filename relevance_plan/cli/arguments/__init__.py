"""The command line's own argument types, each checked while the command line is read.

``numbers`` (numeric options and their ranges), ``choices`` (options naming one of a set) and
``paths`` (file arguments, checked by the project rather than by click): a bad value is one line
and the exit code of ``exitcodes``, before any command runs.
"""
