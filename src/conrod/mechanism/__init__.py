"""mechanism stage of the conrod pipeline."""
