"""Motion from rest by time integration: the RK4 transient, and the reference integrators the exact solvers
are checked against (SciPy solve_ivp, Newmark).
"""
