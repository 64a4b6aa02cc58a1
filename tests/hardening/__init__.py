"""Hardening tests: fuzzing, hostile inputs, edit storms, limits, persistence and what is read."""
