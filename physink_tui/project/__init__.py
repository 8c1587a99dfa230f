"""The project file (``.physink.json``): a scene, its timeline and the user's words as versioned JSON, never pickle.

`codec` turns a `codec.Project` into text and back, checking every field; `files` saves atomically and loads.
An edge package: the core (scene, timeline, sim) never imports it.
"""
