"""The session: the single consumer of timestamped inputs and the only writer of state; no UI of its own."""
