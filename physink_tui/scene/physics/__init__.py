"""The physics layer shared by sketch, adjust and demo modes and by SIMULATE: the pymunk world, settling,
pushing clear, and the step-and-observe loop; no I/O, no clock."""
