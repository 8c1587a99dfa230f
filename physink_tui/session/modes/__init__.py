"""The session's modes as objects (sketch, adjust, demo), each with its own world, behind one small interface
(`base.Mode`); they see the session only through `base.Host` and never import it."""
