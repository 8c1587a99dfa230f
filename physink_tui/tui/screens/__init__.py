"""The TUI's screens: the main control panel and its modal dialogs."""
