"""The equations of motion as data: the 1-DOF mesh problem, the mesh inside a structure, the piecewise-linear
system the exact solvers take, the backlash problem, and the choices of contact law and solution method.
"""
