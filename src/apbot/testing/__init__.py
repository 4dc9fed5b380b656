"""Test tooling shipped with the package: the random model generator and brute-force BFS.

They sit above the planner (BFS is the reference the planner is proved against, the
generator draws goals from random walks) and below nothing: no product module (agent,
bench, cli) imports them, so a bug here can fail a check but never change a result. They
ship in the package rather than under ``tests/`` because ``benchmarks/`` uses them too.
"""
