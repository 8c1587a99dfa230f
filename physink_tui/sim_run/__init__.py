"""Runs the parameter search (`physink_tui.sim.search`) with an executor: serially or in local processes."""
