"""Benchmarks users can run: ``python -m toonmesh.bench {smooth,edges,render,all}``.

Each suite times toonmesh side by side with the peer libraries in the same run (median of
repeated runs) and prints ratios, so the numbers stay comparable on a noisy machine.
"""
