"""The exact periodic steady state of linear time-periodic systems: the 1-DOF mesh (closed-form kernels,
batches for sweeps) and n-DOF systems (monodromy, run and chunk routes, solves shared between
callers, the motion from a state).
"""
