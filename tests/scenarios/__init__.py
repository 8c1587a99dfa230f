"""The thesis's reference machines, drawn with the virtual pen, and the journals made from them."""
