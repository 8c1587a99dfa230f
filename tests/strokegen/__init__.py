"""Seeded generators of hand-drawn strokes (shapes, a modelled hand and tablet) for tests and benchmarks only."""
