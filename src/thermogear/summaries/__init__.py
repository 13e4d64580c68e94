"""Summaries of a case as the commands and the report show them: what the mesh model gives, gathered into plain
JSON objects and figures (damping, the paper's thermal stiffness, the thermo-elastic mesh). They sit above the
mesh model and below the interfaces."""
