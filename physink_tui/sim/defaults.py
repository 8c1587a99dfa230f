"""SIMULATE's defaults (seed and budget), in one place for every driver of the search; no behaviour."""

DEFAULT_SEED = 0
"""The random seed a search gets when none is given."""

DEFAULT_BUDGET = 200
"""The most rollouts a search runs when no budget is given."""
