"""Draws scene snapshots into frames, videos and terminal images; decides nothing about the scene itself."""
