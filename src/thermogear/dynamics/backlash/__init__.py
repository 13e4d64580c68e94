"""The nonsmooth (backlash, contact-loss, clearance) responses: the event-driven kernel, periodic orbits by
shooting for 1 and n DOF, the orbits a start reaches, multi-start searches and continuation in speed.
"""
