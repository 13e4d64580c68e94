"""What a case chooses by name, declared once and read below the schema: each module here resolves a family of
choices into what the rest of the package asks (never compared as a string elsewhere) and imports nothing of
thermogear's layers above the temperature limits and the errors, so the schema's checks, the case loader and the
models all read the same declaration:

- :mod:`~thermogear.choices.drivetrain` — a ``[drivetrain]`` end's kind and the pinion's turning sense;
- :mod:`~thermogear.choices.friction` — what each friction law takes from the case (a coefficient, a lubricant
  factor);
- :mod:`~thermogear.choices.thermal_models` — each ``[thermal] model``'s input rules (limits, X_te, its own keys).

The package itself imports nothing.
"""
