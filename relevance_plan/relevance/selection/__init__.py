"""Selection: from scores to the objects an attempt keeps, each decision with its reason.

From the bottom up (each module imports only modules listed before it)::

    closure.py      constraint closure: what the kept objects depend on, and why
    repair.py       what a selection that fails the relaxed check lacks, found by growing it
    prune.py        select -> close -> set aside -> repair -> finish, as one result; widening
    decisions.py    each object's decision, named by the step that made it
    completion.py   a first selection completed for the negative preconditions the check
                    passes over

The repair and the completion run the relaxed check (``reachability``) but are stages of the
selection: they grow a selection and say why each object came back, in closure's terms.
"""
