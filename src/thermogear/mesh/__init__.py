"""The mesh model: the one reader of a case for physics, and the state of one mesh period it hands the solvers."""
