"""The reproduction of Luo & Li (2020) in one place, each part at its own layer of the package (the layers contract
in ``pyproject.toml``; this module imports nothing, so importing one part does not import the others):

- :mod:`thermogear.luo2020.thermal` — the paper's thermal stiffness model k_T and X_te (Eqs. 7–23), the
  ``"luo2020"`` pair model (physics);
- :mod:`thermogear.luo2020.rig` — the paper's FZG rig: its measured data (Table 3, §5.2) and the prediction of
  its temperatures by the gearbox network (beside the test-rig workflow of :mod:`thermogear.experiment`);
- :mod:`thermogear.luo2020.report` — every number of the paper beside thermogear's (the table, its values, rows
  and checks) and the report's rig section (beside :mod:`thermogear.report`).

Reference: Luo & Li (2020), Investigation on the influence of heat on the dynamic characteristics of a gear
transmission system, Engineering Failure Analysis 108, 104724 (``docs/validation.md``: what is reproduced).
"""
