"""contact stage of the conrod pipeline."""
