"""Helical gears: the pair as its transverse section plus a helix (ISO 21771), the contact lines on the plane of
action, and the mesh stiffness of the pair as thin transverse slices staggered along the face.

β = 0 is the spur pair exactly: the transverse section is then the pair itself and every slice sits at the same
phase, so every helical quantity reduces to the spur one bit for bit where the spur code computes it.
"""
