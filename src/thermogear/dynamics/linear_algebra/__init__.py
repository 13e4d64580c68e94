"""Linear algebra of a period made of pieces, knowing nothing of the system: matrix exponentials (batched,
shared Padé, rank updates), their powers and products, groups of nearly equal pieces, the range of a
monodromy, the closed-form 2×2 kernels of the 1-DOF mesh.
"""
