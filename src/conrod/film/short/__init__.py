"""The short-bearing (Ocvirk) film: closed-form force, Booker's massless inversion, the
piezoviscous short film and the two-land film of a central groove."""
