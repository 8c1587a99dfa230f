"""What the corpus says: commands of the grammar, near-misses (a name or verb swapped for one that sounds alike),
sentences outside the grammar; what each must give is the grammar's parse with `LABELS`."""

from __future__ import annotations

LABELS = ("ball", "platform", "knife", "egg", "paddle", "frying pan", "basket")
"""The labels the corpus is heard with (`physink listen --labels ball,platform,...`, issue 29)."""

COMMANDS = (
    "label ball", "label platform", "label knife", "label egg", "label paddle", "label frying pan", "label basket",
    "label ramp", "label cup", "label spring", "label lever", "label rope", "label wheel", "label box",
    "label hammer", "label bucket",
    "the ball falls", "the ball hits the platform", "the egg lands in the frying pan", "the knife cuts the rope",
    "the ball rolls down the ramp", "the paddle hits the ball", "the egg drops into the basket",
    "the ball bounces off the platform", "the lever pushes the egg", "the spring launches the ball",
    "the cup falls into the basket", "the ball slides along the platform", "the knife slices the egg",
    "the egg cracks", "the paddle swings", "the ball enters the basket", "the platform tilts",
    "the ball rests on the platform", "the pulley lifts the box", "the hammer strikes the egg",
    "the domino knocks the block", "the box slides off the ramp", "ball hits paddle", "egg falls", "the wheel turns",
    "the seesaw tips", "the rope swings", "the basket catches the egg",
)
NEAR_MISSES = (
    # out of the grammar: a name or verb that sounds like one of it
    "label bell", "label bowl", "label wall", "label packet", "label kite", "label leg", "label the elephant",
    "label pin", "the bell falls", "the doll falls", "the egg stands in the frying pan", "the ball sings",
    "the bottle falls", "the knife cuts the soap", "the ball hits the plate", "the wave hits the ball",
    # in the grammar, but close to another sentence of it
    "the ball fills", "label marble", "the egg glides in the frying pan", "the ball tips", "label peg",
)
OUT_OF_GRAMMAR = (
    "what time is it", "please open the window", "the cat sat on the mat", "hello there how are you",
    "turn on the lights in the kitchen", "i think it needs to be a bit bigger", "can you undo that",
    "no not that one", "okay let me try again", "where did the ball go", "this is going to be fun",
    "move it a little to the left",
)
