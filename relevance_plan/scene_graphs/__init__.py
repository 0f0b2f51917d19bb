"""3D scene graphs in: a robot's Hydra scene graph (or a Matterport3D house) as a planning problem.

An optional extra (``pip install 'relevance-plan[hydra]'``, which brings MIT
SPARK's ``spark-dsg``).  The layers of a Hydra graph become the objects and
facts of the shipped ``hydra`` domain (``domains/hydra/domain.pddl``):

- ``graph``: the graph as plain values (nodes, edges, label names), read from
  spark-dsg by ``dsg``, the only module that imports it; ``house`` builds a
  graph from a Matterport3D ``.house`` file with spark-dsg's converter;
- ``classes``: what each semantic label is (the graph's label space, a
  user's mapping, the text model) and what its class affords;
- ``naming`` and ``problem``: the PDDL objects and facts, with every object
  traced back to its graph node (the sidecar);
- ``goals``: goals as atoms over the imported names, or in words, resolved
  to class goals;
- ``live``: successive graphs (files, or spark-dsg's ZMQ stream) turned into
  the live session's events.

Importing this package imports neither spark-dsg nor numpy.
"""
