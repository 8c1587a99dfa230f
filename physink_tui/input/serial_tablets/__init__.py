"""Serial pen tablets (ISDV4/TPC protocol): probing, decoding, reading."""
