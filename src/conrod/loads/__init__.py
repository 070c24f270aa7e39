"""loads stage of the conrod pipeline."""
