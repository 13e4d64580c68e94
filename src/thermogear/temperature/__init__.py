"""Tooth temperatures: the field of the thermal model and its checks (field), the kinds of source chosen once
(kinds), the one set of temperature limits (limits), and the temperature input of a case (source).
"""
