"""Atomic result files: a crash never leaves a half-written file."""

from conrod.io.atomic import atomic_path, write_csv, write_json, write_text

__all__ = ["atomic_path", "write_csv", "write_json", "write_text"]
