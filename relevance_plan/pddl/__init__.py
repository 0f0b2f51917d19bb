"""The PDDL layer: s-expressions, the model, formulas, the parser, the formatter,
the cutting writer, plans and the builtin simulator."""
