"""Ball-and-platform machines made by construction, with known answers (issue 27): a seeded generator of drawings,
demonstrations a gravity simulation can follow (each with its witness parameters; `levers` adds a pivoted lever the
ball tips) and demonstrations none can."""
