"""dynamics stage of the conrod pipeline."""
