"""The tabulated squeeze-force field of the Reynolds film ([D0]) and Booker's mobility on the
same map: one model, two formulations."""
