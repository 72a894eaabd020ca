"""Small scenes the tests share (text as a user writes it, kept short so a run is quick)."""

#: A heavy top over 0.05 s, 3 samples: M g l = 0.981 J, tilted 0.5 rad, spun at 10 rad/s.
HEAVY_TOP = """\
title = "A heavy top"
[body]
I1 = 1.0
I3 = 0.5
[gravity]
M = 1.0
g = 9.81
l = 0.1
[initial]
alpha = 0.0
beta = 0.5
gamma = 0.0
alpha_dot = 0.0
beta_dot = 0.0
gamma_dot = 10.0
[simulate]
t_end = 0.05
samples = 3
"""
