"""The TUI's widgets: thin views of `SessionView` snapshots that post intent messages."""
