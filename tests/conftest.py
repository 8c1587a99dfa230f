"""Test-wide settings: a session raises its internal errors (a user's session only reports them and carries on), and
Hypothesis draws the same examples whichever test modules are loaded."""

from hypothesis.internal.conjecture import providers

from physink_tui.session.session import Session

Session.raise_internal_errors = True

# Hypothesis (6.13x on) mixes literal constants from every local module in sys.modules into what it draws, so a
# derandomised property met different examples when the whole suite was collected than when its file ran alone
# (test_beautify_bounds' reverse property: a strict xfail alone, passing in the suite). Its examples must depend on
# the test alone: no local constants (Hypothesis's own constant pool is kept).
if hasattr(providers, "_get_local_constants"):
    providers._get_local_constants = lambda: providers._local_constants  # stays empty: never filled
