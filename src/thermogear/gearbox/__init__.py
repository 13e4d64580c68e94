"""The gearbox around the gear pair: power losses, heat transfer and the thermal network (how hot it gets).

Modules: :mod:`mesh_loss` (load-dependent tooth friction loss), :mod:`bearing_loss` (rolling bearings and seals),
:mod:`churning` (no-load dip-lubrication loss), :mod:`convection` (heat-transfer correlations),
:mod:`network` (a lumped thermal network solver that knows no gears), :mod:`description` and :mod:`model` (the
gearbox as a network: steady state and warm-up), :mod:`bulk_temperature` (the quick estimate) and
:mod:`backlash` (backlash over a warm-up). Nothing heavy is imported here.
"""
