"""The session journal (``.physink.jsonl``): every timestamped input of a session, append-only, replayable.

``entries`` holds the values, ``checks`` the rules, ``codec`` and ``header_codec`` the JSON lines, ``writer``
appends them durably and ``reader`` reads them back. Replaying the entries is the session's job, not this package's.
"""
