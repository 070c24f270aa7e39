"""Numerical building blocks below every physical layer: the damped Newton iteration of a
step system (own unknowns and journal degrees of freedom solved together)."""
