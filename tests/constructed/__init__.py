"""Ball-and-platform machines made by construction, with known answers (issue 27): a seeded generator of drawings,
demonstrations a gravity simulation can follow (each with its witness parameters; `levers` adds a pivoted lever the
ball tips; `springs` a trampoline on a vertical spring that catches the ball, its spring part of the witness) and
demonstrations none can."""
