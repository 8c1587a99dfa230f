"""The project file (``.physink.json``): a scene, its timeline and the user's words as versioned JSON, never
pickle."""
