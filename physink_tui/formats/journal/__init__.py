"""The session journal (``.physink.jsonl``): entries, their JSON lines, durable appending and reading back;
replaying is the session's job."""
