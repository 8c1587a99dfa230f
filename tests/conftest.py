"""Test-wide settings: a session raises its internal errors (a user's session only reports them and carries on)."""

from physink_tui.session.session import Session

Session.raise_internal_errors = True
