"""Modes of a structure on matrices: undamped and damped modes, rigid-body modes and the reduction onto their
complement, the modal reduction with static correction.
"""
