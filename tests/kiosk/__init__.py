"""Helpers for the kiosk's tests: tablet captures of kiosk visits made with the virtual pen."""
