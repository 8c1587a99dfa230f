"""File formats in one place: journal, project and timeline codecs, their JSON checks and versions; reading and
writing, no session logic."""
