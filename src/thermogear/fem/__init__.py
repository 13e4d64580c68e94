"""Finite-element verification of the tooth model (issue 7): rack-generated tooth outline and mesh, steady bulk
temperature (scikit-fem), elastic and thermo-elastic tooth deformation, X_te from FE runs, and the ``"fem"``
providers of the temperature field and of X_te (:mod:`thermogear.fem.provider`).

Heavy modules (scikit-fem, triangle) are imported by the submodules only.
"""
