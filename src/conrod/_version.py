"""The package version, importable without importing anything else of conrod."""

__version__ = "0.1.0"
