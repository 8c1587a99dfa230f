"""The headless kiosk recording service (`physink kiosk`): a driver of the session with no UI, never Textual.

`service.Kiosk` waits for a tablet, starts a session when the pen first touches, takes its controls from hot zones
along an edge of the tablet (`hot_zones`, `controls`), ends a session on its zone or after an idle time, and has
`finalise` write the session's outputs into a folder of its own that `store.SessionStore` keeps (``index.jsonl``,
recovery of unfinished sessions, retiring old ones).
"""
