"""One module per ``physink`` subcommand, each a ``run(args) -> int`` driving the session; cli parses."""
