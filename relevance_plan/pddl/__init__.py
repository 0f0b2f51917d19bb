"""The PDDL layer: text in, immutable values, text out; plans and their simulation.

sexpr.py      s-expressions with source positions
model.py      Domain, Problem, actions, metrics: immutable values
formulas.py   conditions, effects and expressions as typed nodes, and one walk over them
parser.py     PDDL text -> Domain and Problem
formatter.py  Domain, Problem and formulas -> PDDL text
writer.py     the pruned problem: the user's own file minus the pruned objects
plans.py      plans in the IPC format, sequential and timed
simulator.py  the builtin plan simulator (the builtin validator)
compile.py    features compiled away, and plans mapped back
"""
